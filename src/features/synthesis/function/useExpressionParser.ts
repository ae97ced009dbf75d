import { use } from 'react';
import { benchMark } from '../../../shared/benchMarks';
import type { parseExpression } from './expression';

/** The parse function, or null when its chunk could not be loaded. */
export type ExpressionParser = typeof parseExpression | null;

/** The parser module, loaded once on first use (math.js is its own chunk: the rest of the app never loads it). */
let parser: Promise<ExpressionParser> | null = null;

/**
 * Starts loading the parser (once) and returns the promise of its parse function; it never rejects: a failed load
 * resolves to null (the page then asks for a reload; retrying on render would suspend again on every render).
 */
export function loadExpressionParser(): Promise<ExpressionParser> {
  if (!parser) {
    benchMark('synmode-fx-parser-start');
    parser = import('./expression').then(
      (m) => {
        benchMark('synmode-fx-parser-ready');
        return m.parseExpression;
      },
      () => null,
    );
  }
  return parser;
}

/** The expression parser (null if it failed to load), suspending the caller inside a Suspense boundary until then. */
export function useExpressionParser(): ExpressionParser {
  return use(loadExpressionParser());
}
