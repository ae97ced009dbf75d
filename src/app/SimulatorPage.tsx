import { Suspense, lazy, useState } from 'react';
import { LinkageStage } from '../features/simulator/LinkageStage';
import { DragHint } from '../features/simulator/phone/DragHint';
import { createForceLayer } from '../features/forces/forceLayer';
import { shellMessages } from './shellMessages';
import { SimulatorPlots } from './SimulatorPlots';
import type { SimulatorSession } from './useSimulatorSession';

// The transmission plot (its chart module) loads after the first paint (see SimulatorPageProps.lateShown).
const TransmissionPanel = lazy(() =>
  import('../features/simulator/TransmissionPanel').then((m) => ({ default: m.TransmissionPanel })),
);

/** Props of SimulatorPage: the session, and whether the parts that follow the first frame are shown yet. */
export interface SimulatorPageProps {
  session: SimulatorSession;
  /**
   * The transmission plot is mounted and the θ4 chart drawn: after the first frame, and on a phone (where they are
   * below the fold) after the first answers, with the results column (AppLayout), so they do not hold up the first
   * screen.
   */
  lateShown: boolean;
}

/** The full app's simulator page: the linkage, its angle plots and the transmission plot. */
export function SimulatorPage({ session, lateShown }: SimulatorPageProps) {
  const { state, t, cycle, design, deg, xMarks, plotsRef } = session;
  const shell = shellMessages(state.shell.locale);
  // The pin-force arrows the canvas draws while Forces and its arrows are on (the forces feature computes them).
  const [forceLayer] = useState(createForceLayer);
  return (
    <>
      <section className="card stage">
        <LinkageStage
          cycle={cycle}
          design={design}
          onViewChange={session.onViewChange}
          onTheta2={session.onTheta2}
          onCoupler={session.onCoupler}
          onSize={session.onCanvasSize}
          hint={shell.canvasHint({ crank: true, coupler: true })}
          onShown={session.onShown}
          forceLayer={forceLayer}
          stage={session.stage}
        />
        <DragHint locale={state.shell.locale} />
      </section>
      <section className="card plots" aria-label={t.sectionPlots} ref={plotsRef}>
        <SimulatorPlots session={session} secondHeld={!lateShown} />
      </section>
      <section className="card transmission-card" aria-label={t.chartTransmission}>
        {lateShown ? (
          <Suspense fallback={null}>
            <TransmissionPanel
              deg={deg}
              muBandLoDeg={state.display.muBandLoDeg}
              muBandHiDeg={state.display.muBandHiDeg}
              xMarks={xMarks}
            />
          </Suspense>
        ) : null}
      </section>
    </>
  );
}
