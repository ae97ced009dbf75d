import { radToDeg, wrapDeg360 } from '../../solver/angles';
import type { DesignMetrics } from '../../solver/metrics';
import type { InputRange } from '../../solver/types';
import { LIMIT_INSET_DEG, assemblesAnywhere, rangeToDeg } from '../state/animation';
import { formatDeg, formatNumber } from '../format';
import { sliderIntervals } from '../state/inputRange';

/** Decimals of the angles in the design panel (a designer compares them with a textbook's three). */
export const DESIGN_DECIMALS = 3;

/** Significant digits of the time ratio in the design panel. */
export const TIME_RATIO_DIGITS = 5;

/** A place on the input's cycle the panel can go to: theta2 in the slider's [0, 360) convention and as text. */
export interface DesignStop {
  theta2Deg: number;
  theta2Text: string;
}

/** A dead centre as the panel shows it: where the input is, and the rocker angle there (degrees, text). */
export interface DeadCentreFact extends DesignStop {
  kind: 'extended' | 'folded';
  theta4Text: string;
}

/** Everything the design panel shows, already formatted; null fields are not applicable to this linkage. */
export interface DesignFacts {
  muMinText: string;
  muMinAt: DesignStop;
  muMaxText: string;
  muMaxAt: DesignStop;
  /** Extended then folded, on the current branch; null unless the input is a crank driving a rocker. */
  deadCentres: DeadCentreFact[] | null;
  swingText: string | null;
  timeRatioText: string | null;
  /** A rocking input's limits in slider order (each interval's start then end); go-to targets sit a hair inside. */
  limits: DesignStop[];
}

function stop(theta2Deg: number): DesignStop {
  const deg = wrapDeg360(theta2Deg);
  return { theta2Deg: deg, theta2Text: formatDeg(deg, DESIGN_DECIMALS) };
}

/**
 * Formats designMetrics (radians) for the panel, or null for a linkage that assembles nowhere (it has no μ, no
 * dead centre and no limit to show): angles in degrees to DESIGN_DECIMALS, every theta2 in the
 * slider's [0, 360) convention, the time ratio to TIME_RATIO_DIGITS significant digits. range is the input's
 * reachable range: a rocking input (not full, not empty) lists its limits, each go-to target inset by
 * LIMIT_INSET_DEG into the reachable side so the pose assembles there.
 */
export function designFacts(m: DesignMetrics, range: InputRange): DesignFacts | null {
  if (!assemblesAnywhere(range)) return null;
  const tr = m.transmission;
  const deg = (rad: number) => formatDeg(radToDeg(rad), DESIGN_DECIMALS);
  const deadCentres: DeadCentreFact[] | null = m.output
    ? (['extended', 'folded'] as const).map((kind) => {
        const dc = m.output![kind];
        return { kind, ...stop(radToDeg(dc.theta2)), theta4Text: deg(dc.theta4) };
      })
    : null;
  const limits: DesignStop[] = [];
  if (!range.full) {
    for (const iv of sliderIntervals(rangeToDeg(range).intervals)) {
      const width = iv.wraps ? iv.hiDeg + 360 - iv.loDeg : iv.hiDeg - iv.loDeg;
      const inset = Math.min(LIMIT_INSET_DEG, width / 2);
      limits.push(
        { theta2Deg: wrapDeg360(iv.loDeg + inset), theta2Text: formatDeg(iv.loDeg, DESIGN_DECIMALS) },
        { theta2Deg: wrapDeg360(iv.hiDeg - inset), theta2Text: formatDeg(iv.hiDeg, DESIGN_DECIMALS) },
      );
    }
  }
  return {
    muMinText: `${deg(tr.min)}°`,
    muMinAt: stop(radToDeg(tr.theta2AtMin)),
    muMaxText: `${deg(tr.max)}°`,
    muMaxAt: stop(radToDeg(tr.theta2AtMax)),
    deadCentres,
    swingText: m.output ? `${deg(m.output.swing)}°` : null,
    timeRatioText: m.timeRatio === null ? null : formatNumber(m.timeRatio, TIME_RATIO_DIGITS),
    limits,
  };
}

/** The dead-centre theta2 values (degrees, slider convention) with their kind, for the rules on theta2 axes. */
export function deadCentreMarks(m: DesignMetrics | null): { theta2Deg: number; kind: 'extended' | 'folded' }[] {
  if (!m || !m.output) return [];
  return (['extended', 'folded'] as const).map((kind) => ({
    theta2Deg: wrapDeg360(radToDeg(m.output![kind].theta2)),
    kind,
  }));
}
