import { useState } from 'react';
import { ControlsPanel } from '../features/simulator/ControlsPanel';
import { LinkageStage } from '../features/simulator/LinkageStage';
import { createForceLayer } from '../features/forces/forceLayer';
import type { EmbedViewProps } from './embedPages';
import { EmbedPanels } from './EmbedPanels';
import { shellMessages } from './shellMessages';

/** The simulator's embed: the linkage with the controls beside it, then the panels the URL asks for. */
export function SimulatorEmbed({ session, embed }: EmbedViewProps) {
  const { state, dispatch, rocking, design, onStep, onShown } = session;
  const { onCanvasSize, onTheta2, onCoupler, onViewChange } = session;
  const [forceLayer] = useState(createForceLayer);
  const show = (p: (typeof embed.panels)[number]) => embed.panels.includes(p);
  const crankMovable = !embed.locked.includes('theta2');
  const couplerMovable = !embed.locked.includes('coupler');
  const shell = shellMessages(state.shell.locale);
  return (
    <>
      <div className={`embed-body${show('controls') ? ' with-controls' : ''}`}>
        <div className="embed-stage">
          <LinkageStage
            cycle={session.cycle}
            design={design}
            onViewChange={onViewChange}
            onTheta2={crankMovable ? onTheta2 : undefined}
            onCoupler={couplerMovable ? onCoupler : undefined}
            onSize={onCanvasSize}
            hint={shell.canvasHint({ crank: crankMovable, coupler: couplerMovable })}
            onShown={onShown}
            forceLayer={forceLayer}
            stage={session.stage}
          />
        </div>
        {show('controls') ? (
          <div className="embed-controls">
            <ControlsPanel
              state={state}
              dispatch={dispatch}
              locked={embed.locked}
              compact
              rocking={rocking}
              onStep={onStep}
            />
          </div>
        ) : null}
      </div>
      <EmbedPanels session={session} show={show} theta2Locked={!crankMovable} />
    </>
  );
}
