/** A value outside React that views read with useSyncExternalStore: its current value and a subscription to changes. */
export interface ValueSource<T> {
  /** The current value (stable between changes). */
  get(): T;
  /** Adds a change listener; returns its removal. */
  subscribe(listener: () => void): () => void;
}

/**
 * One value outside React with get, set and subscribe for useSyncExternalStore: only the views that read it
 * re-render when it changes (Object.is), not the tree around them.
 */
export class ExternalValue<T> implements ValueSource<T> {
  private readonly listeners = new Set<() => void>();

  constructor(private value: T) {}

  /** The current value (stable between sets). */
  readonly get = (): T => this.value;

  /** Sets the value and tells the subscribers when it changed. */
  set(value: T): void {
    if (Object.is(value, this.value)) return;
    this.value = value;
    for (const listener of [...this.listeners]) listener();
  }

  /** Adds a change listener; returns its removal. */
  readonly subscribe = (listener: () => void): (() => void) => {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  };
}
