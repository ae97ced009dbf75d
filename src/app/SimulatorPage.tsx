import { Suspense, lazy, useState } from 'react';
import { LinkageStage } from '../features/simulator/LinkageStage';
import { DragHint } from '../features/simulator/phone/DragHint';
import { createForceLayer } from '../features/forces/forceLayer';
import { shellMessages } from './shellMessages';
import { SimulatorPlots } from './SimulatorPlots';
import type { SimulatorSession } from './useSimulatorSession';

// The transmission plot (its chart module) loads after the first paint.
const TransmissionPanel = lazy(() =>
  import('../features/simulator/TransmissionPanel').then((m) => ({ default: m.TransmissionPanel })),
);

/** The full app's simulator page: the linkage, its angle plots and the transmission plot. */
export function SimulatorPage({ session }: { session: SimulatorSession }) {
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
        />
        <DragHint locale={state.shell.locale} />
      </section>
      <section className="card plots" aria-label={t.sectionPlots} ref={plotsRef}>
        <SimulatorPlots session={session} />
      </section>
      <section className="card transmission-card" aria-label={t.chartTransmission}>
        <Suspense fallback={null}>
          <TransmissionPanel
            deg={deg}
            muBandLoDeg={state.display.muBandLoDeg}
            muBandHiDeg={state.display.muBandHiDeg}
            xMarks={xMarks}
          />
        </Suspense>
      </section>
    </>
  );
}
