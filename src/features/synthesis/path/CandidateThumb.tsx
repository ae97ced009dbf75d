import type { Point } from '../../../solver/kinematics';
import { emptyBounds, extendBounds } from '../../../shared/canvas/view';

/** Props of CandidateThumb: the coupler curve (NaN breaks it) and the targets, in the task's plane. */
export interface CandidateThumbProps {
  curve: { x: ArrayLike<number>; y: ArrayLike<number> };
  targets: readonly Point[];
  size?: number;
}

/** A small SVG of a candidate's coupler curve through the targets (decorative: the list item names it). */
export function CandidateThumb({ curve, targets, size = 64 }: CandidateThumbProps) {
  const b = emptyBounds();
  for (const t of targets) extendBounds(b, t.x, t.y);
  for (let i = 0; i < curve.x.length; i++) extendBounds(b, curve.x[i], curve.y[i]);
  const span = Math.max(b.maxX - b.minX, b.maxY - b.minY) || 1;
  const k = (size - 8) / span;
  const cx = (b.minX + b.maxX) / 2;
  const cy = (b.minY + b.maxY) / 2;
  const sx = (x: number) => size / 2 + (x - cx) * k;
  const sy = (y: number) => size / 2 - (y - cy) * k;
  let d = '';
  let pen = false;
  for (let i = 0; i < curve.x.length; i++) {
    const x = curve.x[i];
    const y = curve.y[i];
    if (!Number.isFinite(x) || !Number.isFinite(y)) {
      pen = false;
      continue;
    }
    d += `${pen ? 'L' : 'M'}${sx(x).toFixed(1)} ${sy(y).toFixed(1)}`;
    pen = true;
  }
  return (
    <svg className="syn-thumb" width={size} height={size} viewBox={`0 0 ${size} ${size}`} aria-hidden="true">
      <path d={d} fill="none" stroke="var(--trace)" strokeWidth={1.5} />
      {targets.map((t, i) => (
        <circle key={i} cx={sx(t.x)} cy={sy(t.y)} r={2.5} fill="none" stroke="var(--accent-2)" strokeWidth={1.25} />
      ))}
    </svg>
  );
}
