import type { Point } from '../../../solver/kinematics';
import { formatDeg, formatNumber } from '../../../shared/format';
import type { Messages } from '../../../shared/i18n/messages';
import { NumberField } from '../../../shared/ui/NumberField';
import { SelectMenu } from '../../../shared/ui/SelectMenu';
import { Toggle } from '../../../shared/ui/Toggle';
import type { NinePointClass } from '../../../synthesis/ninePoint/ninePointSynthesis';
import { CandidateThumb } from '../path/CandidateThumb';
import type { SynthesisMessages } from '../synthesisMessages';
import type { NineClassFacts, NineFilters } from './nineClassFacts';
import type { NinePointMessages, NineSort } from './ninePointMessages';

/** Props of NineClassList: the classes with their facts, the points, the filters, which is chosen, and the edits. */
export interface NineClassListProps {
  classes: readonly NinePointClass[];
  facts: readonly NineClassFacts[];
  /** Indices of the classes the filters keep, in the order shown. */
  shown: readonly number[];
  points: readonly Point[];
  filters: NineFilters;
  onFilters: (f: NineFilters) => void;
  chosen: number;
  onChoose: (index: number) => void;
  nt: NinePointMessages;
  st: SynthesisMessages;
  t: Messages;
}

const SORTS: readonly NineSort[] = ['found', 'size', 'transmission'];

/** The filters: Grashof, crank input, no circuit/order defect, a size bound, and the sort order. */
function Filters({ filters, onFilters, nt }: Pick<NineClassListProps, 'filters' | 'onFilters' | 'nt'>) {
  const set = (p: Partial<NineFilters>) => onFilters({ ...filters, ...p });
  return (
    <fieldset className="nine-filters">
      <legend className="syn-field-label">{nt.filtersLegend}</legend>
      <div className="nine-toggles">
        <Toggle label={nt.filterGrashof} checked={filters.grashof} onChange={(grashof) => set({ grashof })} />
        <Toggle label={nt.filterCrank} checked={filters.crank} onChange={(crank) => set({ crank })} />
        <Toggle label={nt.filterNoDefect} checked={filters.noDefect} onChange={(noDefect) => set({ noDefect })} />
      </div>
      <NumberField
        label={nt.maxSizeLabel}
        value={filters.maxSize}
        className="syn-field"
        placeholder="—"
        errorText={(text) => nt.maxSizeError(text)}
        check={(x) => (x > 0 ? null : 'positive')}
        onCommit={(maxSize) => set({ maxSize })}
        onClear={() => set({ maxSize: null })}
      />
      <p className="note">{nt.maxSizeHelp}</p>
      <label className="nine-sort">
        <span className="syn-field-label">{nt.sortLabel}</span>
        <SelectMenu
          label={nt.sortLabel}
          value={filters.sort}
          options={SORTS.map((s) => ({ value: s, label: nt.sortText[s] }))}
          onChange={(sort) => set({ sort })}
        />
      </label>
    </fieldset>
  );
}

/**
 * Every real class found: the count ("64 real linkage classes, 192 linkages"), the filters and sort, and the classes
 * kept, each a button (pressed when chosen) with its thumbnail, longest link, type, transmission and defects.
 */
export function NineClassList(props: NineClassListProps) {
  const { classes, facts, shown, points, chosen, onChoose, nt, st, t } = props;
  const fmt = (x: number) => formatNumber(x, 4);
  return (
    <section className="card syn-card" aria-labelledby="nine-classes-title">
      <h3 id="nine-classes-title" className="syn-card-title">
        {nt.classesTitle}
      </h3>
      <p className="nine-count" data-testid="nine-count" data-classes={classes.length}>
        {classes.length > 0 ? nt.classCount(classes.length, 3 * classes.length) : nt.noClasses}
      </p>
      {classes.length > 0 ? <Filters {...props} /> : null}
      {classes.length > 0 ? (
        <p className="note" data-testid="nine-shown">
          {shown.length > 0 ? nt.shownCount(shown.length, classes.length) : nt.noneMatch}
        </p>
      ) : null}
      <ol className="syn-candidates nine-classes" data-testid="nine-classes">
        {shown.map((i) => {
          const c = classes[i];
          const f = facts[i];
          const first = f.cognates[0];
          return (
            <li key={i}>
              <button
                type="button"
                className={`syn-candidate${i === chosen ? ' is-chosen' : ''}`}
                aria-pressed={i === chosen}
                onClick={() => onChoose(i)}
              >
                <CandidateThumb curve={first.curve} targets={points} />
                <span className="syn-candidate-text">
                  <strong>{nt.className(i + 1)}</strong>
                  <span>
                    {t.types[first.type]} · {c.grashof ? st.grashof : st.nonGrashof} ·{' '}
                    {f.crank ? nt.crankInput : nt.noCrank}
                  </span>
                  <span>
                    {nt.longestLink} {fmt(f.size)} · μ {formatDeg(f.muMinDeg, 1)}°
                  </span>
                  <span className={c.defects.length > 0 ? 'syn-defects' : undefined}>
                    {nt.defectsLabel}:{' '}
                    {c.defects.length > 0 ? c.defects.map((d) => nt.defectText[d]).join('; ') : nt.noDefects}
                  </span>
                </span>
              </button>
            </li>
          );
        })}
      </ol>
    </section>
  );
}
