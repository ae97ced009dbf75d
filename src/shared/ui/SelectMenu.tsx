/** Props of SelectMenu: its accessible name, the chosen value, the choices and what a choice does. */
export interface SelectMenuProps<T extends string> {
  label: string;
  value: T;
  options: readonly { value: T; label: string }[];
  onChange: (value: T) => void;
  /** Default 'select select-small'. */
  className?: string;
  disabled?: boolean;
}

/** A native menu of labelled string choices (its options' values are the choices themselves). */
export function SelectMenu<T extends string>({
  label,
  value,
  options,
  onChange,
  className = 'select select-small',
  disabled,
}: SelectMenuProps<T>) {
  return (
    <select
      className={className}
      aria-label={label}
      value={value}
      disabled={disabled}
      onChange={(e) => onChange(e.target.value as T)}
    >
      {options.map((o) => (
        <option key={o.value} value={o.value}>
          {o.label}
        </option>
      ))}
    </select>
  );
}
