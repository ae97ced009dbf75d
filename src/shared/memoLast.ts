/**
 * f with a cache of one: called with the same arguments as last time (Object.is, one by one) it returns the last
 * result, the same object, as React's useMemo does for its dependencies; pure code memoizes with it outside React.
 */
export function memoLast<A extends unknown[], R>(f: (...args: A) => R): (...args: A) => R {
  let last: { args: A; result: R } | null = null;
  return (...args: A): R => {
    if (last && last.args.length === args.length && last.args.every((a, i) => Object.is(a, args[i]))) {
      return last.result;
    }
    const result = f(...args);
    last = { args, result };
    return result;
  };
}
