import { parseDecimal } from '../../shared/decimal';
import { truncateText } from '../../shared/format';
import type { SpatialField } from '../../shared/state/slices/spatialSlice';
import { SPATIAL_FIELDS, normalizeSpatial, spatialFieldProblem } from '../../shared/state/slices/spatialSlice';
import type { FieldRead } from '../../shared/ui/NumberControl';
import { NumberControlView, useFieldDraft } from '../../shared/ui/NumberControl';
import { ECHO_MAX_CHARS } from '../../shared/ui/validateNumber';
import type { SpatialMessages } from './spatialMessages';

/** The slider's range and step of a field (the typed field takes anything its spec allows). */
export interface SliderRange {
  min: number;
  max: number;
  step: number;
}

/** Props of SpatialFieldControl: the field, its value, the slider's range, the commit and the strings. */
export interface SpatialFieldControlProps {
  field: SpatialField;
  value: number;
  slider: SliderRange;
  onCommit: (value: number) => void;
  sm: SpatialMessages;
  /** Decimals the field shows (trailing zeros dropped); absent: the exact value. */
  decimals?: number;
  /** Locked by an embed: shown read-only with the lock mark, the slider disabled; default false. */
  locked?: boolean;
}

/** The allowed range of a field as text: (0, 180)°. */
export function rangeText(field: SpatialField): string {
  const f = SPATIAL_FIELDS[field];
  const n = (x: number) => (Math.abs(x) >= 1e6 ? x.toExponential(0) : String(x));
  return `${f.minOpen ? '(' : '['}${n(f.min)}, ${n(f.max)}${f.maxOpen ? ')' : ']'}${f.angle ? '°' : f.unit ? ` ${f.unit}` : ''}`;
}

/**
 * A slider and a field for one spatial value (the shared NumberControlView and useFieldDraft). A typed value outside
 * the field's range or not a number shows a message naming the field and the text and keeps the last valid value;
 * Escape restores it.
 */
export function SpatialFieldControl(props: SpatialFieldControlProps) {
  const { field, value, slider, onCommit, sm, decimals, locked = false } = props;
  const label = sm.fieldNames[field];
  const { angle, unit } = SPATIAL_FIELDS[field];
  const read = (text: string): FieldRead => {
    const echo = truncateText(text.trim(), ECHO_MAX_CHARS);
    const x = parseDecimal(text);
    if (Number.isNaN(x)) return { ok: false, message: sm.notNumber(label, echo) };
    const v = normalizeSpatial(field, x);
    if (spatialFieldProblem(field, v) !== null)
      return { ok: false, message: sm.fieldError(label, echo, rangeText(field)) };
    return { ok: true, value: v };
  };
  const draft = useFieldDraft(value, decimals, !locked, read, onCommit);
  return (
    <NumberControlView
      label={label}
      field={draft}
      unit={angle ? '°' : (unit ?? '')}
      locked={locked}
      slider={{
        ...slider,
        value,
        onSlide: (x) => {
          const v = normalizeSpatial(field, x);
          if (locked || spatialFieldProblem(field, v) !== null) return;
          draft.clearError();
          onCommit(v);
        },
      }}
    />
  );
}
