import { useCallback, useState } from 'react';

/**
 * The fields in error (name → message), and the callback a field reports to (null: no longer in error); the map is
 * the same object while nothing changes.
 */
export function useFieldErrors(): [ReadonlyMap<string, string>, (name: string, error: string | null) => void] {
  const [fieldErrors, setFieldErrors] = useState<ReadonlyMap<string, string>>(new Map());
  const onFieldError = useCallback((name: string, error: string | null) => {
    setFieldErrors((m) => {
      if ((m.get(name) ?? null) === error) return m;
      const next = new Map(m);
      if (error === null) next.delete(name);
      else next.set(name, error);
      return next;
    });
  }, []);
  return [fieldErrors, onFieldError];
}
