import './ColumnTable.css';
import type { ReactNode } from 'react';

/** Props of ColumnTable: the table's class, its column titles and its body rows. */
export interface ColumnTableProps {
  /** Class of the table (its look is the feature's). */
  className: string;
  /** Column titles, left to right: one header cell each (scope col); a title may be visually hidden. */
  columns: readonly ReactNode[];
  /** The body's rows (<tr> elements). */
  children: ReactNode;
}

/** A table with a row of column titles in a box that scrolls sideways when the table is wider than the page. */
export function ColumnTable({ className, columns, children }: ColumnTableProps) {
  return (
    <div className="column-table-scroll">
      <table className={className}>
        <thead>
          <tr>
            {columns.map((title, i) => (
              <th key={i} scope="col">
                {title}
              </th>
            ))}
          </tr>
        </thead>
        <tbody>{children}</tbody>
      </table>
    </div>
  );
}
