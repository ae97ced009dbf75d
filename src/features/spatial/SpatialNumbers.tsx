import { radToDeg } from '../../solver';
import { formatDeg, formatNumber } from '../../shared/format';
import type { SpatialPose, Vec3 } from '../../spatial';
import type { SpatialMessages } from './spatialMessages';
import type { SpatialAnalysis } from './useSpatialAnalysis';

/** Props of SpatialNumbers: the analysis, the pose and μ at θ2 (null where the loop cannot close), the strings. */
export interface SpatialNumbersProps {
  analysis: SpatialAnalysis;
  pose: SpatialPose | null;
  muRad: number | null;
  theta2Deg: number;
  sm: SpatialMessages;
}

/** A range of angles in radians as degrees text, "full turn" for a full range. */
function rangeText(range: SpatialAnalysis['classification']['inputRange'], sm: SpatialMessages): string {
  if (range.full) return sm.fullTurn;
  if (!range.intervals.length) return '—';
  return range.intervals.map((iv) => `${formatDeg(radToDeg(iv.lo))}° … ${formatDeg(radToDeg(iv.hi))}°`).join(', ');
}

function PinRow({ name, p, id }: { name: string; p: Vec3 | undefined; id: string }) {
  const cell = (v: number | undefined, axis: string) => (
    <td className="num" data-testid={`pin-${id}-${axis}`}>
      {v === undefined ? '—' : formatNumber(v, 7)}
    </td>
  );
  return (
    <tr>
      <th scope="row">{name}</th>
      {cell(p?.x, 'x')}
      {cell(p?.y, 'y')}
      {cell(p?.z, 'z')}
    </tr>
  );
}

/** The numbers at θ2 (output angle, rates, μ, the pins) and of the cycle (type, input range, swing, μ range). */
export function SpatialNumbers({ analysis, pose, muRad, theta2Deg, sm }: SpatialNumbersProps) {
  const { classification: c, motion } = analysis;
  const swing = motion.swings.map((w) => `${formatDeg(radToDeg(w.swing))}°`).join(', ') || '—';
  const mu = motion.transmission;
  const hasP = analysis.model.kind === 'spherical' && analysis.model.linkage.pDist !== undefined;
  return (
    <div className="spatial-numbers">
      <dl className="spatial-facts">
        <dt>{sm.typeLabel}</dt>
        <dd data-testid="spatial-type">{sm.typeNames[c.type]}</dd>
        <dt>{sm.inputRange}</dt>
        <dd>{rangeText(c.inputRange, sm)}</dd>
        <dt>{sm.outputSwing}</dt>
        <dd>{swing}</dd>
        <dt>{sm.transmissionRange}</dt>
        <dd>{mu ? `${formatDeg(radToDeg(mu.min))}° … ${formatDeg(radToDeg(mu.max))}°` : '—'}</dd>
      </dl>
      <h3 className="spatial-subtitle">
        {sm.numbersTitle} = {formatDeg(theta2Deg)}°
      </h3>
      {pose ? (
        <>
          <dl className="spatial-facts">
            <dt>θ4</dt>
            <dd data-testid="spatial-theta4">{formatDeg(radToDeg(pose.theta4), 4)}°</dd>
            <dt>ω4</dt>
            <dd data-testid="spatial-omega4">{formatNumber(pose.omega4, 6)} rad/s</dd>
            <dt>α4</dt>
            <dd data-testid="spatial-alpha4">{formatNumber(pose.alpha4, 6)} rad/s²</dd>
            <dt>{sm.transmission}</dt>
            <dd>{muRad === null ? '—' : `${formatDeg(radToDeg(muRad))}°`}</dd>
          </dl>
          <table className="spatial-pins">
            <thead>
              <tr>
                <th scope="col">
                  <span className="sr-only">pin</span>
                </th>
                <th scope="col">x</th>
                <th scope="col">y</th>
                <th scope="col">z</th>
              </tr>
            </thead>
            <tbody>
              <PinRow name={sm.pinA} p={pose.A} id="A" />
              <PinRow name={sm.pinB} p={pose.B} id="B" />
              {hasP ? <PinRow name={sm.pinP} p={pose.P} id="P" /> : null}
            </tbody>
          </table>
          <p className="note">
            {sm.omegaNote(formatNumber(analysis.input.omega2, 6), formatNumber(analysis.input.alpha2, 6))}
          </p>
        </>
      ) : (
        <p className="spatial-warning" role="status">
          {sm.cannotClose(`${formatDeg(theta2Deg)}°`)}
        </p>
      )}
    </div>
  );
}
