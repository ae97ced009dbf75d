import '../motion/synthesisModes.css';
import { Suspense, useMemo } from 'react';
import type { Dispatch } from 'react';
import { degToRad } from '../../../solver';
import type { Action, AppState } from '../../../shared/state/appState';
import { useMessages } from '../../../shared/i18n/MessagesContext';
import { COLORS } from '../../../shared/theme/tokens';
import type { OpenDesign } from '../openDesign';
import { functionMessagesFor } from './functionMessages';
import { useExpressionParser } from './useExpressionParser';
import { useSweep } from './useSweep';
import { generatedAt } from './functionSolve';
import { structuralErrorData, useFunctionDesign } from './useFunctionDesign';
import { FunctionSweep } from './FunctionSweep';
import { FunctionDesignCard } from './FunctionDesignCard';
import { ExpressionField } from './ExpressionField';
import { FunctionFields } from './FunctionFields';
import { FunctionCanvas } from './FunctionCanvas';
import { StructuralErrorChart } from './StructuralErrorChart';
import { SynthesisPrint } from '../print/SynthesisPrint';
import { synthesisMessagesFor } from '../synthesisMessages';
import { functionPrintContent } from './functionPrint';

/** Props of FunctionMode (as the synthesis page renders every mode). */
export interface FunctionModeProps {
  state: AppState;
  dispatch: Dispatch<Action>;
  /** "Open in simulator" with the design (no markers: a function generator has no points in the plane). */
  onOpen: (design: OpenDesign) => void;
}

/** Everything that needs the parser: it suspends until math.js has loaded. */
function FunctionBody({ state, dispatch, onOpen }: FunctionModeProps) {
  const t = useMessages();
  const fm = functionMessagesFor(state.shell.locale);
  const s = state.synFunction;
  const parse = useExpressionParser();
  const { fd, f, problem } = useFunctionDesign(s, parse, fm);
  const sweep = useSweep(s, fd !== null);
  const at = fd && f ? generatedAt(s, fd, f, sweep.x) : null;
  const chart = useMemo(() => structuralErrorData(fd, fm), [fd, fm]);
  if (!parse) return <p className="note note-error">{fm.parserFailed}</p>;

  return (
    <div className="synmode-mode synmode-function" data-testid="function-mode" data-ready={fd ? 'true' : 'false'}>
      <div className="synmode-function-main">
        <section className="card synmode-canvas-card synmode-function-canvas" aria-label={fm.canvasLabel}>
          {fd && at ? (
            <FunctionCanvas
              picture={{
                fd,
                theta2Range: [degToRad(s.theta2RangeDeg[0]), degToRad(s.theta2RangeDeg[1])],
                theta4Range: [degToRad(s.theta4RangeDeg[0]), degToRad(s.theta4RangeDeg[1])],
                theta2: at.theta2,
              }}
              labels={{ canvas: fm.canvasLabel, zoomIn: t.zoomIn, zoomOut: t.zoomOut, resetView: t.resetView }}
            />
          ) : (
            <p className="note synmode-empty">{fm.noDesign}</p>
          )}
        </section>
        {fd && at ? <FunctionSweep sweep={sweep} xRange={s.xRange} want={at.want} got={at.got} fm={fm} /> : null}
        {fd && at ? (
          <section className="card synmode-chart-card" aria-label={fm.errorChartTitle}>
            <StructuralErrorChart
              data={chart}
              marker={{ x: sweep.x, dots: [{ y: at.got - at.want, color: COLORS.residual }] }}
              texts={{ title: fm.errorChartTitle, xLabel: fm.errorChartX, yLabel: fm.errorChartY }}
            />
          </section>
        ) : null}
      </div>
      <section className="card synmode-side" aria-label={fm.expressionLabel}>
        <p className="note">{fm.intro}</p>
        <ExpressionField
          value={s.expression}
          parse={parse}
          onCommit={(expression) => dispatch({ type: 'setSynFunction', patch: { expression } })}
          fm={fm}
        />
        <FunctionFields s={s} dispatch={dispatch} fm={fm} />
        {problem ? (
          <p className="note note-error" role="status" data-testid="function-problem">
            {problem}
          </p>
        ) : null}
        {fd ? (
          <FunctionDesignCard
            fd={fd}
            onOpen={() => onOpen({ design: fd.design, markers: [], theta2: degToRad(s.theta2RangeDeg[0]) })}
            fm={fm}
            t={t}
          />
        ) : null}
      </section>
      <SynthesisPrint
        m={synthesisMessagesFor(state.shell.locale).print}
        build={() =>
          functionPrintContent({
            s,
            fd,
            problem,
            unit: state.design.lengthUnit,
            st: synthesisMessagesFor(state.shell.locale),
            fm,
            t,
          })
        }
      />
    </div>
  );
}

/**
 * Function generation (函數生成): y = f(x) typed as an expression (math.js, loaded on first use, never evaluating
 * JavaScript), the x, θ2 and θ4 ranges and the precision points; the function generator moving through its range,
 * its structural error (結構誤差) against x with the precision points (精確點) marked, its defects in words, and
 * Open in simulator.
 */
export function FunctionMode(props: FunctionModeProps) {
  const fm = functionMessagesFor(props.state.shell.locale);
  return (
    <Suspense
      fallback={
        <p className="note" role="status" data-testid="function-loading">
          {fm.loadingParser}
        </p>
      }
    >
      <FunctionBody {...props} />
    </Suspense>
  );
}
