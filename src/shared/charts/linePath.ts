/**
 * SVG path data of a polyline: d3-shape's `line()` with its default linear curve, character for character (a run
 * of defined points is `M x,y L x,y …`, a lone defined point `M x,yZ`), with d3-path's rounding to `digits`
 * decimals (3 by default, as d3's). The simulator's charts draw with this: d3-shape ships as one bundle whose curve factories
 * cannot be tree-shaken, which would put every curve and symbol (about 4 KB gzip) on the first load (issue 11). The
 * lab's charts, loaded on demand, still use d3-shape.
 */
export function linePath<T>(
  data: ArrayLike<T>,
  x: (d: T, i: number) => number,
  y: (d: T, i: number) => number,
  defined: (d: T, i: number) => boolean = () => true,
  digits = 3,
): string {
  const k = 10 ** Math.floor(digits);
  const num = (v: number) => Math.round(v * k) / k;
  let out = '';
  let run = 0;
  for (let i = 0; i < data.length; i++) {
    const d = data[i];
    if (!defined(d, i)) {
      if (run === 1) out += 'Z';
      run = 0;
      continue;
    }
    out += `${run === 0 ? 'M' : 'L'}${num(+x(d, i))},${num(+y(d, i))}`;
    run++;
  }
  if (run === 1) out += 'Z';
  return out;
}
