import { solveClosedForm } from '../../../src/solver/closedForm';
import { transmissionAngle } from '../../../src/solver/kinematics';
import type { Branch, Linkage } from '../../../src/solver/types';
import type { BranchExtent, LinkageScene, SceneText } from '../../../src/shared/linkage/scene';
import { sceneBounds, scenePose } from '../../../src/shared/linkage/scene';
import type { LabelFont, MeasureText } from '../../../src/shared/linkage/sceneLayout';
import { FONT_SIZES } from '../../../src/shared/theme/tokens';

/** A named test linkage with a coupler point (distance in its unit, angle in degrees). */
export interface TestLinkage {
  name: string;
  linkage: Linkage;
  coupler: { distance: number; angleDeg: number };
}

/** The linkages of the label sweep: the report's case, a drag link, a parallelogram, a near-toggle, a tiny crank, a triple rocker. */
export const LINKAGES: readonly TestLinkage[] = [
  { name: "report's 6-2-5-5", linkage: { r1: 6, r2: 2, r3: 5, r4: 5 }, coupler: { distance: 2.5, angleDeg: 30 } },
  { name: 'drag link', linkage: { r1: 2, r2: 4, r3: 4.5, r4: 5 }, coupler: { distance: 2, angleDeg: 25 } },
  { name: 'parallelogram', linkage: { r1: 4, r2: 2, r3: 4, r4: 2 }, coupler: { distance: 2, angleDeg: 0 } },
  {
    name: 'near-toggle crank-rocker',
    linkage: { r1: 4, r2: 1, r3: 3, r4: 2.000000001 },
    coupler: { distance: 1.5, angleDeg: 40 },
  },
  { name: 'tiny crank', linkage: { r1: 6, r2: 0.05, r3: 5, r4: 5 }, coupler: { distance: 2.5, angleDeg: 30 } },
  { name: 'triple rocker', linkage: { r1: 4, r2: 3, r3: 3.5, r4: 3 }, coupler: { distance: 1.5, angleDeg: 20 } },
];

/** Canvas texts in English or Traditional Chinese, with fixed number formats. */
export function sceneText(lang: 'en' | 'zh-TW', warning: boolean, theta2Deg: number): SceneText {
  const zh = lang === 'zh-TW';
  return {
    O2: 'O2',
    O4: 'O4',
    A: 'A',
    B: 'B',
    P: 'P',
    warning: warning
      ? zh
        ? `θ2 = ${theta2Deg.toFixed(2)}° 時無法組裝`
        : `Cannot assemble at θ2 = ${theta2Deg.toFixed(2)}°`
      : null,
    warningDetail: warning ? (zh ? '可達 θ2：−136.0° … 136.0°' : 'Reachable θ2: −136.0° … 136.0°') : null,
    gridSpacing: (s) => (zh ? `格距 ${s}` : `grid ${s}`),
    formatAngle: (d) => `${d.toFixed(1)}°`,
    formatLength: (x) => String(Number(x.toPrecision(4))),
  };
}

const FONT_PX: Record<LabelFont, number> = { regular: FONT_SIZES.canvas, bold: FONT_SIZES.canvasBold };

/**
 * A deterministic text width model (CSS pixels): CJK and full-width characters 1 em, everything else
 * 0.62 em, bold 8 % wider. It errs wide of a real sans-serif (Latin averages about 0.55 em).
 */
export const measureModel: MeasureText = (text, font) => {
  let em = 0;
  for (const ch of text) {
    const c = ch.codePointAt(0)!;
    em += (c >= 0x2e80 && c <= 0x9fff) || (c >= 0xff00 && c <= 0xffef) ? 1 : 0.62;
  }
  return em * FONT_PX[font] * (font === 'bold' ? 1.08 : 1);
};

/** Degrees to radians (tests only; src uses the units module). */
export const rad = (deg: number) => (deg * Math.PI) / 180;

/** Scenes of a linkage at every step of theta2 (degrees) on a branch, with bounds over the whole sweep of both branches. */
export function sweepScenes(
  t: TestLinkage,
  branch: Branch,
  lang: 'en' | 'zh-TW',
  stepDeg = 1,
  flags: Partial<Pick<LinkageScene, 'showGrid' | 'showAngles' | 'showGhost' | 'showTrace'>> = {},
): LinkageScene[] {
  const l = t.linkage;
  const c = { distance: t.coupler.distance, angleRad: rad(t.coupler.angleDeg) };
  const other: Branch = branch === 'open' ? 'crossed' : 'open';
  const degs: number[] = [];
  for (let d = 0; d < 360; d += stepDeg) degs.push(d);
  const extent = (b: Branch): BranchExtent => {
    const theta4: number[] = [];
    const px: number[] = [];
    const py: number[] = [];
    for (const d of degs) {
      const a = solveClosedForm(l, rad(d), b);
      const p = a ? scenePose(l, { theta2: rad(d), ...a, mu: transmissionAngle(a) }, c) : null;
      theta4.push(a ? a.theta4 : Number.NaN);
      px.push(p ? p.P.x : Number.NaN);
      py.push(p ? p.P.y : Number.NaN);
    }
    return { theta4, px, py };
  };
  const bounds = sceneBounds(l, [extent(branch), extent(other)], [], []);
  return degs.map((d) => {
    const pose = (b: Branch) => {
      const a = solveClosedForm(l, rad(d), b);
      return a ? scenePose(l, { theta2: rad(d), ...a, mu: transmissionAngle(a) }, c) : null;
    };
    const p = pose(branch);
    return {
      linkage: l,
      theta2: rad(d),
      pose: p,
      ghost: pose(other),
      curves: [],
      showGrid: true,
      showAngles: true,
      showGhost: true,
      showTrace: true,
      ...flags,
      text: sceneText(lang, p === null, d),
      bounds,
    };
  });
}

/** One drawing call recorded by RecordingContext, with the state that styles it. */
export interface DrawCall {
  op: 'fillText' | 'strokeText' | 'stroke' | 'fill' | 'fillRect';
  fillStyle: string;
  strokeStyle: string;
  lineWidth: number;
  font: string;
  text?: string;
  x?: number;
  y?: number;
}

/** A 2D context stand-in that records every fill, stroke and text call (and measures with measureModel). */
export class RecordingContext {
  calls: DrawCall[] = [];
  fillStyle = '#000000';
  strokeStyle = '#000000';
  lineWidth = 1;
  font = `${FONT_SIZES.canvas}px sans-serif`;
  textAlign = 'start';
  textBaseline = 'alphabetic';
  lineCap = 'butt';
  lineJoin = 'miter';
  private stack: Pick<RecordingContext, 'fillStyle' | 'strokeStyle' | 'lineWidth' | 'font'>[] = [];

  private record(op: DrawCall['op'], text?: string, x?: number, y?: number): void {
    const { fillStyle, strokeStyle, lineWidth, font } = this;
    this.calls.push({ op, fillStyle, strokeStyle, lineWidth, font, text, x, y });
  }
  save(): void {
    this.stack.push({
      fillStyle: this.fillStyle,
      strokeStyle: this.strokeStyle,
      lineWidth: this.lineWidth,
      font: this.font,
    });
  }
  restore(): void {
    Object.assign(this, this.stack.pop());
  }
  measureText(text: string): { width: number } {
    const bold = /^(600|bold)\b/.test(this.font);
    return { width: measureModel(text, bold ? 'bold' : 'regular') };
  }
  fillText(text: string, x: number, y: number): void {
    this.record('fillText', text, x, y);
  }
  strokeText(text: string, x: number, y: number): void {
    this.record('strokeText', text, x, y);
  }
  stroke(): void {
    this.record('stroke');
  }
  fill(): void {
    this.record('fill');
  }
  fillRect(): void {
    this.record('fillRect');
  }
  beginPath(): void {}
  closePath(): void {}
  moveTo(): void {}
  lineTo(): void {}
  arc(): void {}
  roundRect(): void {}
  setLineDash(): void {}
}

/**
 * The report's linkage (6-2-5-5, P at 2.5 and 0.5 rad) at theta2 on the open branch, grid and angles on, in a fixed
 * frame, with extras (motion vectors, pin forces) merged in: the scene the vector and force overlay tests draw.
 */
export function reportScene(theta2Deg: number, extras: Partial<LinkageScene> = {}): LinkageScene {
  const l = { r1: 6, r2: 2, r3: 5, r4: 5 };
  const t2 = rad(theta2Deg);
  const a = solveClosedForm(l, t2, 'open');
  if (!a) throw new Error('no pose');
  const pose = scenePose(
    l,
    { theta2: t2, theta3: a.theta3, theta4: a.theta4, mu: 1 },
    { distance: 2.5, angleRad: 0.5 },
  );
  return {
    linkage: l,
    theta2: t2,
    pose,
    ghost: null,
    curves: [],
    showGrid: true,
    showAngles: true,
    showGhost: false,
    showTrace: false,
    text: sceneText('en', false, theta2Deg),
    bounds: { minX: -2.5, maxX: 11, minY: -5, maxY: 7 },
    ...extras,
  };
}
