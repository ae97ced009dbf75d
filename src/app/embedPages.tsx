import { Suspense, lazy } from 'react';
import type { ReactNode } from 'react';
import type { EmbedOptions, EmbedPage } from '../shared/url/url';
import { SimulatorEmbed } from './SimulatorEmbed';
import type { SimulatorSession } from './useSimulatorSession';

/** What a page's embed view is drawn from: the widget's session and the embed's panels and locks for this page. */
export interface EmbedViewProps {
  session: SimulatorSession;
  embed: EmbedOptions;
}

// The mechanism and spatial pages (three.js) load only when an embed shows them.
const MechanismEmbed = lazy(() => import('./MechanismEmbed').then((m) => ({ default: m.MechanismEmbed })));
const SpatialEmbed = lazy(() => import('./SpatialEmbed').then((m) => ({ default: m.SpatialEmbed })));

/**
 * Each page that embeds (PAGE_EMBEDS in shared/url/embedOptions.ts says which, with their panels and locks) and its
 * view in the widget; a page PAGE_EMBEDS gives options and this table forgets is a type error. Kept apart from
 * pages.tsx (the app's tabs and views) because <fourbar-lab> is one file with every import inlined: it must not
 * carry the pages that do not embed.
 */
export const EMBED_VIEWS: Readonly<Record<EmbedPage, (props: EmbedViewProps) => ReactNode>> = {
  simulator: (props) => <SimulatorEmbed {...props} />,
  mechanism: (props) => (
    <Suspense fallback={null}>
      <MechanismEmbed {...props} />
    </Suspense>
  ),
  spatial: (props) => (
    <Suspense fallback={null}>
      <SpatialEmbed {...props} />
    </Suspense>
  ),
};
