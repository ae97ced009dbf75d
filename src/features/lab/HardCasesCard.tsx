import type { Dispatch } from 'react';
import type { Action } from '../../shared/state/appState';
import { HARD_CASES } from './hardCases';
import type { HardCase } from './hardCases';
import type { LabMessages } from './labMessages';

/** Props of HardCasesCard: the dispatch a chosen case is applied through, the lab's strings. */
export interface HardCasesCardProps {
  lt: LabMessages;
  dispatch: Dispatch<Action>;
}

/** The preset a hard case applies: its linkage, θ2 and branch, with the coupler point at mid-coupler, 30°. */
function applyCase(c: HardCase): Action {
  return {
    type: 'applyPreset',
    linkage: c.linkage,
    theta2Deg: c.theta2Deg,
    branch: c.branch,
    coupler: { distance: c.linkage.r3 / 2, angleDeg: 30 },
  };
}

/** The lab's hard cases, each a button that loads it into the simulator's state. */
export function HardCasesCard({ lt, dispatch }: HardCasesCardProps) {
  return (
    <section className="card lab-card" aria-labelledby="lab-hard">
      <h2 id="lab-hard" className="section-title">
        {lt.labHardCases}
      </h2>
      <p className="note">{lt.labHardCasesIntro}</p>
      <ul className="hard-cases">
        {HARD_CASES.map((c) => (
          <li key={c.id}>
            <button type="button" className="hard-case" onClick={() => dispatch(applyCase(c))}>
              <span className="hard-case-name">
                {c.number}. {lt.hardCaseNames[c.id]}
              </span>
              <span className="hard-case-note">{lt.hardCaseNotes[c.id]}</span>
            </button>
          </li>
        ))}
      </ul>
    </section>
  );
}
