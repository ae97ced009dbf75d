/** Props of ShareText: the text, its accessible name and its height in rows. */
export interface ShareTextProps {
  value: string;
  label: string;
  rows: number;
}

/** A read-only text to copy by hand (a link or embed code), selected whole when it takes focus. */
export function ShareText({ value, label, rows }: ShareTextProps) {
  return (
    <textarea
      className="share-text"
      readOnly
      value={value}
      aria-label={label}
      rows={rows}
      onFocus={(e) => e.currentTarget.select()}
    />
  );
}
