import { SpatialPage } from '../features/spatial/SpatialPage';
import type { EmbedViewProps } from './embedPages';

/**
 * The spatial page's embed (page=3d): the 3D view, the controls (panel controls; lock=params, theta2, branch, play),
 * the numbers at θ2 (info) and the plots (plots).
 */
export function SpatialEmbed({ session, embed }: EmbedViewProps) {
  const show = (p: (typeof embed.panels)[number]) => embed.panels.includes(p);
  const locked = (l: (typeof embed.locked)[number]) => embed.locked.includes(l);
  return (
    <SpatialPage
      state={session.state}
      dispatch={session.dispatch}
      embed={{
        controlsShown: show('controls'),
        numbersShown: show('info'),
        plotsShown: show('plots'),
        locks: { params: locked('params'), theta2: locked('theta2'), branch: locked('branch'), play: locked('play') },
      }}
    />
  );
}
