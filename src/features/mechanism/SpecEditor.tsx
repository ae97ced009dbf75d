import { useState } from 'react';
import { GROUND } from '../../mechanism';
import type { MechanismSpec } from '../../mechanism';
import { degToRad, radToDeg } from '../../solver/angles';
import { NumberField } from '../../shared/ui/NumberField';
import { ColumnTable } from '../../shared/ui/ColumnTable';
import type { MechMessages } from './mechMessagesEn';
import {
  deleteJoint,
  deleteLink,
  makeGround,
  renameJoint,
  renameLink,
  setInput,
  setJointLinks,
  setSlideAngle,
  setTracerLink,
  moveJoint,
} from './specEdits';

/** What a tool places on the canvas: a pin, a slider or a tracer. */
export type PlaceKind = 'R' | 'P' | 'T';

/** Props of SpecEditor: the linkage, how to change it, the chosen joint and the traced ones, the tool armed. */
export interface SpecEditorProps {
  spec: MechanismSpec;
  /** Applies an edit; an edit that throws is refused with its message (the linkage kept). */
  edit: (change: (spec: MechanismSpec) => MechanismSpec) => void;
  selected: string | null;
  onSelect: (id: string) => void;
  traced: ReadonlySet<string>;
  onTrace: (id: string, on: boolean) => void;
  /** The links a new part joins (a tracer: the first). */
  newLinks: [string, string];
  onNewLinks: (links: [string, string]) => void;
  /** Arms a tool (the canvas places the part) from a pointer; from the keyboard, places it at the view's centre. */
  onPlace: (kind: PlaceKind, byKeyboard: boolean) => void;
  onNew: () => void;
  onAddLink: () => void;
  onResetTemplate: (() => void) | null;
  m: MechMessages;
}

/** A text field for a name, committed on Enter or blur (a refused name restores the old one). */
function NameField({ label, value, onCommit }: { label: string; value: string; onCommit: (v: string) => void }) {
  const [text, setText] = useState<string | null>(null);
  const commit = () => {
    if (text !== null && text !== value) onCommit(text);
    setText(null);
  };
  return (
    <input
      className="mech-name"
      aria-label={label}
      value={text ?? value}
      onChange={(e) => setText(e.target.value)}
      onBlur={commit}
      onKeyDown={(e) => {
        if (e.key === 'Enter') commit();
        if (e.key === 'Escape') setText(null);
      }}
    />
  );
}

/** A select of the linkage's links. */
function LinkSelect(props: { label: string; links: string[]; value: string; onChange: (l: string) => void }) {
  return (
    <select aria-label={props.label} value={props.value} onChange={(e) => props.onChange(e.target.value)}>
      {props.links.map((l) => (
        <option key={l} value={l}>
          {l}
        </option>
      ))}
    </select>
  );
}

const num = (x: number) => Number(x.toPrecision(12));

/**
 * The linkage's editor: tools (new, add a link, a pin, a slider, a tracer), the input joint, the links (rename, make
 * ground, delete) and a table of joints and tracers (choose, name, links, exact x and y, slide direction, trace,
 * delete). Every control is a labelled form control: the whole editor works from the keyboard.
 */
export function SpecEditor(p: SpecEditorProps) {
  const { spec, edit, m } = p;
  const fieldError = (field: string) => (text: string, kept: string, why: string | null) =>
    m.fieldError(field, text, kept, why);
  const placeButton = (kind: PlaceKind, label: string) => (
    <button type="button" className="btn btn-small" data-place={kind} onClick={(e) => p.onPlace(kind, e.detail === 0)}>
      {label}
    </button>
  );
  return (
    <div className="mech-editor">
      <div className="mech-tools" role="group" aria-label={m.editTitle}>
        <button type="button" className="btn btn-small" onClick={p.onNew}>
          {m.newLinkage}
        </button>
        {p.onResetTemplate && (
          <button type="button" className="btn btn-small" onClick={p.onResetTemplate}>
            {m.resetTemplate}
          </button>
        )}
        <button type="button" className="btn btn-small" onClick={p.onAddLink}>
          {m.addLink}
        </button>
        {placeButton('R', m.addPin)}
        {placeButton('P', m.addSlider)}
        {placeButton('T', m.addTracer)}
      </div>
      <div className="mech-new-links">
        <span>{m.between}</span>
        <LinkSelect
          label={m.newLinkA}
          links={spec.links}
          value={p.newLinks[0]}
          onChange={(l) => p.onNewLinks([l, p.newLinks[1]])}
        />
        <span>{m.and}</span>
        <LinkSelect
          label={m.newLinkB}
          links={spec.links}
          value={p.newLinks[1]}
          onChange={(l) => p.onNewLinks([p.newLinks[0], l])}
        />
        <label className="mech-input-select">
          {m.inputJoint}{' '}
          <select value={spec.input.joint} onChange={(e) => edit((s) => setInput(s, e.target.value))}>
            <option value="">{m.noneChosen}</option>
            {spec.joints.map((j) => (
              <option key={j.id} value={j.id}>
                {j.id}
              </option>
            ))}
          </select>
        </label>
      </div>
      <h3 className="mech-subtitle">{m.linksTitle}</h3>
      <ul className="mech-links">
        {spec.links.map((l) => (
          <li key={l}>
            {l === GROUND ? (
              <span className="mech-ground-name">
                {GROUND} <small>({m.isGround})</small>
              </span>
            ) : (
              <>
                <NameField label={m.linkName(l)} value={l} onCommit={(v) => edit((s) => renameLink(s, l, v))} />
                <button type="button" className="btn btn-small" onClick={() => edit((s) => makeGround(s, l))}>
                  {m.makeGround}
                </button>
                <button
                  type="button"
                  className="btn btn-small"
                  aria-label={m.deleteLink(l)}
                  onClick={() => edit((s) => deleteLink(s, l))}
                >
                  ×
                </button>
              </>
            )}
          </li>
        ))}
      </ul>
      <h3 className="mech-subtitle">{m.jointsTitle}</h3>
      <ColumnTable
        className="mech-table"
        columns={[
          m.colName,
          m.colKind,
          m.colLinks,
          m.colX,
          m.colY,
          m.colAngle,
          m.colTrace,
          <span key="del" className="visually-hidden">
            ×
          </span>,
        ]}
      >
        {[
          ...spec.joints.map((j) => ({ id: j.id, kind: j.kind as 'R' | 'P' | 'T', joint: j, point: null })),
          ...(spec.points ?? []).map((t) => ({ id: t.id, kind: 'T' as const, joint: null, point: t })),
        ].map((row) => {
          const at = row.joint ?? row.point!;
          return (
            <tr key={row.id} className={p.selected === row.id ? 'mech-row-selected' : undefined}>
              <td>
                <span className="mech-name-cell">
                  <input
                    type="radio"
                    name="mech-selected"
                    aria-label={m.select(row.id)}
                    checked={p.selected === row.id}
                    onChange={() => p.onSelect(row.id)}
                  />
                  <NameField
                    label={m.jointName(row.id)}
                    value={row.id}
                    onCommit={(v) => edit((s) => renameJoint(s, row.id, v))}
                  />
                </span>
              </td>
              <td>{row.kind === 'R' ? m.kindR : row.kind === 'P' ? m.kindP : m.kindT}</td>
              <td>
                {row.joint ? (
                  <span className="mech-link-pair">
                    <LinkSelect
                      label={m.jointLinkA(row.id)}
                      links={spec.links}
                      value={row.joint.links[0]}
                      onChange={(l) => edit((s) => setJointLinks(s, row.id, [l, row.joint!.links[1]]))}
                    />
                    <LinkSelect
                      label={m.jointLinkB(row.id)}
                      links={spec.links}
                      value={row.joint.links[1]}
                      onChange={(l) => edit((s) => setJointLinks(s, row.id, [row.joint!.links[0], l]))}
                    />
                  </span>
                ) : (
                  <LinkSelect
                    label={m.jointLinkA(row.id)}
                    links={spec.links}
                    value={row.point!.link}
                    onChange={(l) => edit((s) => setTracerLink(s, row.id, l))}
                  />
                )}
              </td>
              <td>
                <NumberField
                  label={m.jointX(row.id)}
                  hideLabel
                  value={num(at.x)}
                  onCommit={(x) => edit((s) => moveJoint(s, row.id, x, at.y))}
                  errorText={fieldError(m.jointX(row.id))}
                  className="mech-num"
                />
              </td>
              <td>
                <NumberField
                  label={m.jointY(row.id)}
                  hideLabel
                  value={num(at.y)}
                  onCommit={(y) => edit((s) => moveJoint(s, row.id, at.x, y))}
                  errorText={fieldError(m.jointY(row.id))}
                  className="mech-num"
                />
              </td>
              <td>
                {row.joint?.kind === 'P' && (
                  <NumberField
                    label={m.jointAngle(row.id)}
                    hideLabel
                    value={num(radToDeg(row.joint.angle ?? 0))}
                    onCommit={(deg) => edit((s) => setSlideAngle(s, row.id, degToRad(deg)))}
                    errorText={fieldError(m.jointAngle(row.id))}
                    className="mech-num"
                  />
                )}
              </td>
              <td>
                <input
                  type="checkbox"
                  aria-label={m.traceOf(row.id)}
                  checked={p.traced.has(row.id)}
                  onChange={(e) => p.onTrace(row.id, e.target.checked)}
                />
              </td>
              <td>
                <button
                  type="button"
                  className="btn btn-small"
                  aria-label={m.deleteJoint(row.id)}
                  onClick={() => edit((s) => deleteJoint(s, row.id))}
                >
                  ×
                </button>
              </td>
            </tr>
          );
        })}
      </ColumnTable>
    </div>
  );
}
