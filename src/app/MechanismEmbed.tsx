import { MechanismPage } from '../features/mechanism/MechanismPage';
import { mechMessagesFor } from '../features/mechanism/mechMessages';
import { createMechStage } from '../workers/mechStageClient';
import { useMessages } from '../shared/i18n/MessagesContext';
import type { MechTemplateKey } from '../shared/state/slices/mechSlice';
import { MECH_TEMPLATE_KEYS } from '../shared/state/slices/mechSlice';
import type { EmbedViewProps } from './embedPages';

/**
 * The mechanism page's embed (page=mech): the template chooser (unless lock=template), the linkage (dragged unless
 * lock=edit), Play and the input (panel controls), the joints' positions (info) and the two plots (plots).
 */
export function MechanismEmbed({ session, embed }: EmbedViewProps) {
  const { state, dispatch } = session;
  const t = useMessages();
  const m = mechMessagesFor(state.shell.locale);
  const show = (p: (typeof embed.panels)[number]) => embed.panels.includes(p);
  const templateLocked = embed.locked.includes('template');
  return (
    <>
      <label className="embed-mech-template">
        <span>{m.galleryTitle}</span>
        <select
          className="select select-small"
          value={state.mech.template}
          disabled={templateLocked}
          onChange={(e) => dispatch({ type: 'setMechTemplate', template: e.target.value as MechTemplateKey })}
        >
          {MECH_TEMPLATE_KEYS.map((k) => (
            <option key={k} value={k}>
              {m.templateNames[k] ?? k}
            </option>
          ))}
        </select>
        {templateLocked ? <span className="locked">({t.locked})</span> : null}
      </label>
      <MechanismPage
        state={state}
        dispatch={dispatch}
        client={session.client}
        createStage={createMechStage}
        embedded
        embedOptions={{
          driveShown: show('controls'),
          positionsShown: show('info'),
          plotsShown: show('plots'),
          editLocked: embed.locked.includes('edit'),
          positionsLabel: t.embedPositions,
        }}
      />
    </>
  );
}
