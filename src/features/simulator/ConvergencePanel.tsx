import './ConvergencePanel.css';
import type { Dispatch } from 'react';
import { memo, useMemo } from 'react';
import type { Action, NrStart } from '../../shared/state/appState';
import type { PointResponse } from '../../shared/solution';
import { convergenceInputs } from '../../shared/charts/chartInputs';
import { ConvergenceChartView } from '../../shared/charts/ConvergenceChartView';
import { useMessages } from '../../shared/i18n/MessagesContext';
import { Segmented } from '../../shared/ui/Segmented';

/** Props of ConvergencePanel: the latest pose's NR runs and the chosen start. */
export interface ConvergencePanelProps {
  point: PointResponse | null;
  nrStart: NrStart;
  dispatch: Dispatch<Action>;
}

function ConvergencePanelImpl({ point, nrStart, dispatch }: ConvergencePanelProps) {
  const t = useMessages();
  const inputs = useMemo(() => convergenceInputs(point, nrStart, t), [point, nrStart, t]);
  return (
    <div className="convergence-panel">
      <Segmented<NrStart>
        legend={t.nrStartLabel}
        value={nrStart}
        options={[
          { value: 'continuation', label: t.nrContinuation },
          { value: 'cold', label: t.nrCold },
        ]}
        onChange={(v) => dispatch({ type: 'setNrStart', start: v })}
      />
      <ConvergenceChartView inputs={inputs} label={inputs.title} />
    </div>
  );
}

/** The NR convergence chart at the current theta2 with the continuation / cold start switch. */
export const ConvergencePanel = memo(ConvergencePanelImpl);
