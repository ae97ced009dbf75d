import {
  AmbientLight,
  BufferGeometry,
  Float32BufferAttribute,
  Color,
  CylinderGeometry,
  DirectionalLight,
  DoubleSide,
  MeshLambertMaterial,
  FrontSide,
  Group,
  Line,
  LineBasicMaterial,
  LineDashedMaterial,
  LineSegments,
  Mesh,
  MeshBasicMaterial,
  MeshPhongMaterial,
  OrthographicCamera,
  PerspectiveCamera,
  Quaternion,
  Scene,
  SphereGeometry,
  Spherical,
  Vector2,
  Vector3,
  WebGLRenderer,
} from 'three';
import type { InterleavedBufferAttribute, Material, Object3D } from 'three';
import { Line2 } from 'three/addons/lines/Line2.js';
import { LineGeometry } from 'three/addons/lines/LineGeometry.js';
import { LineMaterial } from 'three/addons/lines/LineMaterial.js';
import { LineSegments2 } from 'three/addons/lines/LineSegments2.js';
import { LineSegmentsGeometry } from 'three/addons/lines/LineSegmentsGeometry.js';
import { COLORS } from '../../shared/theme/tokens';
import { PI, TWO_PI, degToRad } from '../../solver';
import type { Vec3 } from '../../spatial';
import type { SceneLinkage, ScenePose } from './sceneData';
import { arcPointsInto, chordPointsInto, sceneBounds } from './sceneData';
import type { RenderQuality } from './renderQuality';
import type { RibbonView } from './screenRibbon';
import { ribbonIndex, ribbonInto, ribbonVertexCount } from './screenRibbon';
import { ADAPT_WINDOW, REST_MS, adaptQuality, pixelRatioFor, qualityForRenderer } from './renderQuality';
import type { SceneEnv } from './sceneEnv';
import { createFixedLayer } from './fixedLayer';
import type { FixedLayerParts } from './fixedLayer';
import { planFixedLayer } from './fixedLayerPlan';
import type { FixedLayerView } from './fixedLayerPlan';
import type { ViewRates } from './keyHold';
import type { PlayRun } from './viewProtocol';

/** How the 3D view projects: perspective (default) or orthographic. */
export type Projection = 'perspective' | 'orthographic';

/** A live three.js view of a spatial linkage on a canvas; every call renders at most once per frame. */
export interface SpatialScene {
  /** The fixed parts (sphere or axes, ground, paths, coupler curve); fits the view when the linkage's size changed. */
  setLinkage(l: SceneLinkage): void;
  /** The moving parts at one pose (null: the loop does not close, the links hidden). */
  setPose(p: ScenePose | null): void;
  setProjection(p: Projection): void;
  /** Back to the first view of this linkage. */
  resetView(): void;
  /** Turns the view about its target (radians: azimuth, then elevation). */
  orbitBy(dAzimuth: number, dElevation: number): void;
  /** Zooms by a factor (> 1 closer). */
  zoomBy(factor: number): void;
  /** Pans by a fraction of the view's height (x right, y up). */
  panBy(dx: number, dy: number): void;
  /** Resizes the drawing buffer to the canvas' CSS size (times the device pixel ratio, given when it changed). */
  resize(widthPx: number, heightPx: number, devicePixelRatio?: number): void;
  /** PNG bytes of the view at scale × its CSS size. */
  pngBytes(scale: number): Promise<Uint8Array>;
  /** Frames rendered so far (for tests and bench). */
  frames(): number;
  /**
   * Only where the view runs Play itself (in its worker, on its own clock): starts Play from the run's θ2 and branch
   * (again with each new run), or stops it (null; the view then shows the last pose set). Absent: the page plays.
   */
  play?(run: PlayRun | null): void;
  /**
   * Only where the view has its own clock (its worker): moves the camera at these speeds on each of its frames until
   * called again (null: still). Absent: the page steps the view at each of a held key's repeats.
   */
  hold?(rates: ViewRates | null): void;
  dispose(): void;
}

const Z_UP = new Vector3(0, 0, 1);
const FOV_DEG = 32;

const v3 = (p: Vec3) => new Vector3(p.x, p.y, p.z);

/** A fat line (pixels wide) through points (x y z flat). */
function fatLine(color: string, widthPx: number, opacity = 1): Line2 {
  const m = new LineMaterial({
    color: new Color(color).getHex(),
    linewidth: widthPx,
    transparent: opacity < 1,
    opacity,
  });
  return new Line2(new LineGeometry(), m);
}

/**
 * A link drawn as a line some pixels wide through `points` (x y z flat, rewritten in place each pose): a fat Line2 whose
 * segment buffer is made once (LineGeometry.setPositions would allocate new buffers every frame), or in the lean look a
 * screen-facing ribbon (screenRibbon.ts) rebuilt before each frame from the points and the view.
 */
interface MovingLine {
  object: Line2 | Mesh;
  points: Float32Array;
  /** Copies points into the line's buffer and marks it for upload (the ribbon: at its next update). */
  commit(): void;
  /** Rebuilds a ribbon for the view; nothing for a Line2, whose shader does it. */
  update(view: RibbonView): void;
}

function movingLine(q: RenderQuality, color: string, widthPx: number, count: number, opacity = 1): MovingLine {
  const points = new Float32Array(3 * count);
  if (!q.fatMovingLines) return ribbon(color, widthPx, points, count, opacity);
  const line = fatLine(color, widthPx, opacity);
  line.geometry.setPositions(points);
  // The pose moves the line anywhere on the unit sphere (or the RSSR's box): no culling on a stale bound.
  line.frustumCulled = false;
  const start = line.geometry.getAttribute('instanceStart') as InterleavedBufferAttribute;
  const segments = start.data.array as Float32Array;
  return {
    object: line,
    points,
    commit() {
      for (let i = 0; i + 1 < count; i++) {
        for (let k = 0; k < 6; k++) segments[6 * i + k] = points[3 * i + k];
      }
      start.data.needsUpdate = true;
    },
    update() {},
  };
}

/** The lean look's line: an unlit triangle strip widthPx wide on screen over count points. */
function ribbon(color: string, widthPx: number, points: Float32Array, count: number, opacity: number): MovingLine {
  const g = new BufferGeometry();
  const position = new Float32BufferAttribute(new Float32Array(3 * ribbonVertexCount(count)), 3);
  g.setAttribute('position', position);
  g.setIndex(ribbonIndex(count));
  const mesh = new Mesh(g, new MeshBasicMaterial({ color, side: DoubleSide, transparent: opacity < 1, opacity }));
  mesh.frustumCulled = false;
  return {
    object: mesh,
    points,
    commit() {},
    update(view) {
      if (!mesh.visible) return;
      ribbonInto(position.array as Float32Array, points, count, view, widthPx);
      position.needsUpdate = true;
    },
  };
}

function setLine(line: Line2, pts: number[]): void {
  if (pts.length < 6) {
    line.visible = false;
    return;
  }
  line.visible = true;
  line.geometry.setPositions(pts);
  line.computeLineDistances();
}

/** Segments of a link's fan; arcPoints gives FAN_STEPS + 1 points. */
const FAN_STEPS = 32;

/** A translucent fan from the sphere's centre to a link's arc: the link seen as the rigid body it is. */
function fan(color: string): Mesh {
  const g = new BufferGeometry();
  g.setAttribute('position', new Float32BufferAttribute(new Float32Array(3 * (FAN_STEPS + 2)), 3));
  const index: number[] = [];
  for (let i = 1; i <= FAN_STEPS; i++) index.push(0, i, i + 1);
  g.setIndex(index);
  const m = new Mesh(
    g,
    new MeshBasicMaterial({ color, transparent: true, opacity: 0.16, side: DoubleSide, depthWrite: false }),
  );
  m.frustumCulled = false;
  return m;
}

/** Puts a fan on the arc's points (x y z flat; the centre is the origin), in place. */
function setFan(m: Mesh, arc: Float32Array): void {
  m.visible = true;
  const pos = m.geometry.getAttribute('position') as Float32BufferAttribute;
  const a = pos.array as Float32Array;
  a[0] = a[1] = a[2] = 0;
  a.set(arc, 3);
  pos.needsUpdate = true;
}

function ball(color: string, radius: number): Mesh {
  return new Mesh(new SphereGeometry(radius, 20, 14), new MeshPhongMaterial({ color, shininess: 40 }));
}

/** A short cylinder along axis at centre: a bearing, the ground symbol of a revolute joint. */
function bearing(radius: number, length: number): Mesh {
  const m = new Mesh(
    new CylinderGeometry(radius, radius, length, 24),
    new MeshPhongMaterial({ color: COLORS.ground, shininess: 20 }),
  );
  return m;
}

function orient(mesh: Object3D, centre: Vector3, axis: Vector3): void {
  mesh.position.copy(centre);
  mesh.quaternion.copy(new Quaternion().setFromUnitVectors(new Vector3(0, 1, 0), axis.clone().normalize()));
}

function disposeTree(root: Object3D): void {
  root.traverse((o) => {
    const m = o as Partial<Mesh>;
    m.geometry?.dispose();
    const mat = m.material as Material | Material[] | undefined;
    if (Array.isArray(mat)) mat.forEach((x) => x.dispose());
    else mat?.dispose();
  });
}

/** A fixed line through points (x y z flat): fat (pixels wide) in the full look, a 1 px line in the lean one. */
function fixedLine(q: RenderQuality, color: string, widthPx: number, pts: number[], opacity = 1): Line2 | Line | null {
  if (pts.length < 6) return null;
  if (q.fatFixedLines) {
    const l = fatLine(color, widthPx, opacity);
    setLine(l, pts);
    return l;
  }
  const g = new BufferGeometry();
  g.setAttribute('position', new Float32BufferAttribute(pts, 3));
  return new Line(g, new LineBasicMaterial({ color, transparent: opacity < 1, opacity }));
}

/** Disjoint segments (pairs of points, x y z flat): fat in the full look, 1 px (dashed as asked) in the lean one. */
function fixedSegments(
  q: RenderQuality,
  segments: number[],
  style: { color: string; widthPx: number; opacity?: number; dash?: [number, number] },
): LineSegments2 | LineSegments {
  const opacity = style.opacity ?? 1;
  const [dashSize, gapSize] = style.dash ?? [0, 0];
  if (q.fatFixedLines) {
    const seg = new LineSegments2(
      new LineSegmentsGeometry(),
      new LineMaterial({
        color: new Color(style.color).getHex(),
        linewidth: style.widthPx,
        dashed: style.dash !== undefined,
        dashSize,
        gapSize,
        transparent: opacity < 1,
        opacity,
      }),
    );
    seg.geometry.setPositions(segments);
    if (style.dash) seg.computeLineDistances();
    return seg;
  }
  const g = new BufferGeometry();
  g.setAttribute('position', new Float32BufferAttribute(segments, 3));
  const m = style.dash
    ? new LineDashedMaterial({ color: style.color, dashSize, gapSize, transparent: opacity < 1, opacity })
    : new LineBasicMaterial({ color: style.color, transparent: opacity < 1, opacity });
  const seg = new LineSegments(g, m);
  if (style.dash) seg.computeLineDistances();
  return seg;
}

/**
 * Makes the view on canvas (the page's, or an OffscreenCanvas in a worker): throws when WebGL cannot start (the caller
 * shows its fallback). Orbit, zoom and pan come from the caller (orbitBy, zoomBy, panBy: keys, and the pointer
 * gestures of viewGestures.ts), so nothing here touches the DOM.
 */
export function createSpatialScene(canvas: HTMLCanvasElement | OffscreenCanvas, env: SceneEnv): SpatialScene {
  let quality = qualityForRenderer(env.rendererName);
  const renderer = new WebGLRenderer({ canvas, antialias: quality.antialias, alpha: false });
  let devicePixelRatio = env.devicePixelRatio;
  const pixelRatio = (moving: boolean) => pixelRatioFor(quality, devicePixelRatio, moving);
  renderer.setPixelRatio(pixelRatio(false));
  const antialias = renderer.getContext().getContextAttributes()?.antialias === true;
  env.onQuality(quality, antialias);
  renderer.setClearColor(new Color(COLORS.surface), 1);
  const scene = new Scene();
  scene.add(new AmbientLight(0xffffff, 1.6));
  const sun = new DirectionalLight(0xffffff, 1.4);
  sun.position.set(2, -3, 5);
  scene.add(sun);

  const perspective = new PerspectiveCamera(FOV_DEG, 1, 0.01, 100);
  const ortho = new OrthographicCamera(-1, 1, 1, -1, -100, 100);
  perspective.up.copy(Z_UP);
  ortho.up.copy(Z_UP);
  let camera: PerspectiveCamera | OrthographicCamera = perspective;
  /** The point the camera looks at and turns about. */
  const target = new Vector3();
  const look = () => {
    camera.lookAt(target);
    camera.updateMatrixWorld();
  };
  let frameCount = 0;
  /** Of them, the frames drawn on the fixed parts' layer. */
  let layerFrames = 0;
  let pending = 0;
  /** When the pending frame was asked for (ms), and the last frames' latencies from ask to draw (adaptQuality). */
  let askedAt = 0;
  const latencies: number[] = [];
  /** When the last frame was drawn (ms), the timer that draws the view at rest after it, and that rest frame asked. */
  let lastFrameAt = Number.NEGATIVE_INFINITY;
  let restTimer: ReturnType<typeof setTimeout> | 0 = 0;
  let restFrame = false;
  let size = new Vector2(1, 1);
  /** The view's fit: centre and radius of the linkage's bounding sphere (scene units). */
  let fit = { centre: new Vector3(), radius: 1.3 };
  let viewDir = new Vector3(0.4, -0.8, 0.5).normalize();

  const render = () => {
    // A frame asked for soon after the last one was drawn is part of a motion (Play, orbit), however long frames take:
    // the lean look draws it with fewer pixels, and once more at full resolution when no change follows within REST_MS
    // of a frame (rest), for the eye and the PNG. A frame drawn directly (resize, PNG) is at rest.
    const inMotion = pending !== 0 && !restFrame && askedAt - lastFrameAt < REST_MS;
    restFrame = false;
    if (pending) {
      latencies.push(performance.now() - askedAt);
      if (latencies.length > ADAPT_WINDOW) latencies.shift();
      const next = adaptQuality(quality, latencies);
      if (next !== quality) lower(next);
    }
    pending = 0;
    const ratio = pixelRatio(inMotion);
    if (ratio !== renderer.getPixelRatio()) {
      renderer.setPixelRatio(ratio);
      renderer.setSize(size.x, size.y, false);
    }
    if (!quality.fatMovingLines) {
      const view = ribbonView();
      for (const m of lines) m.update(view);
    }
    if (drawFrame(inMotion)) layerFrames++;
    frameCount++;
    env.onFrame(frameCount, layerFrames);
    lastFrameAt = performance.now();
    clearTimeout(restTimer);
    restTimer = ratio < pixelRatio(false) ? setTimeout(rest, REST_MS) : 0;
  };
  /** The fixed parts' layer (fixedLayer.ts): the view it was drawn for, the last frame's, and off once it failed. */
  const layer = createFixedLayer(renderer);
  let layerView: FixedLayerView | null = null;
  let lastView: FixedLayerView | null = null;
  let layerFailed = false;
  let fixedBuilds = 0;
  const drawingBuffer = new Vector2();
  const frameView = (): FixedLayerView => {
    camera.updateMatrixWorld();
    renderer.getDrawingBufferSize(drawingBuffer);
    return {
      camera: [...camera.matrixWorld.elements, ...camera.projectionMatrix.elements],
      widthPx: drawingBuffer.x,
      heightPx: drawingBuffer.y,
      build: fixedBuilds,
    };
  };
  /**
   * Draws the frame: in full, or (Play with the camera still, in a look that caches) the moving parts on the layer; true
   * for the latter.
   */
  const drawFrame = (inMotion: boolean): boolean => {
    const view = frameView();
    // A box a pixel wide at the moving look's half resolution has no drawing buffer: nothing to plan (or to draw).
    if (view.widthPx < 1 || view.heightPx < 1) {
      renderer.render(scene, camera);
      return false;
    }
    const plan = planFixedLayer({
      enabled: quality.cacheFixedWhileMoving && !layerFailed,
      moving: inMotion,
      cached: layerView,
      previous: lastView,
      now: view,
    });
    lastView = view;
    const parts: FixedLayerParts = { scene, camera, fixed, moving };
    if (plan === 'build') {
      layerView = layer.build(parts) ? view : null;
      layerFailed = layerView === null;
    }
    if (plan !== 'full' && layerView) {
      layer.draw(parts);
      return true;
    }
    renderer.render(scene, camera);
    return false;
  };
  /** The view at rest (no change asked for since the last frame): one frame at full resolution. */
  const rest = () => {
    restTimer = 0;
    if (pending) return;
    restFrame = true;
    invalidate();
  };
  /** The view as the ribbons need it (scene units per CSS pixel, as Line2's resolution is the CSS size). */
  const ribbonView = (): RibbonView => {
    camera.updateMatrixWorld();
    const forward = camera.getWorldDirection(new Vector3());
    const isPerspective = camera === perspective;
    const unitsPerPx = isPerspective
      ? (2 * Math.tan(degToRad(FOV_DEG / 2))) / (size.y * camera.zoom)
      : (ortho.top - ortho.bottom) / (size.y * ortho.zoom);
    return { eye: camera.position.toArray(), forward: forward.toArray(), perspective: isPerspective, unitsPerPx };
  };
  const invalidate = () => {
    if (pending) return;
    askedAt = performance.now();
    pending = requestAnimationFrame(render);
  };

  // Fixed parts are rebuilt per linkage; moving parts are made once and moved.
  let fixed = new Group();
  scene.add(fixed);
  const lineMaterials: LineMaterial[] = [];
  const track = <T extends Line2 | LineSegments2>(l: T): T => {
    lineMaterials.push(l.material);
    l.material.resolution.copy(size);
    return l;
  };
  const links = [COLORS.crank, COLORS.coupler, COLORS.rocker].map((c) => movingLine(quality, c, 7, FAN_STEPS + 1));
  const [crank, coupler, rocker] = links;
  const pArm = movingLine(quality, COLORS.coupler, 3, FAN_STEPS + 1);
  for (const m of [...links, pArm]) if (m.object instanceof Line2) track(m.object);
  /** The lines rebuilt for the view before each frame (ribbons): the moving ones and the ground link's. */
  let lines: MovingLine[] = [...links, pArm];
  const pinA = ball(COLORS.crank, 0.045);
  const pinB = ball(COLORS.rocker, 0.045);
  const pinP = ball(COLORS.couplerPoint, 0.04);
  const crankFan = fan(COLORS.crank);
  const couplerFan = fan(COLORS.coupler);
  const rockerFan = fan(COLORS.rocker);
  const fans: [Mesh, MovingLine][] = [
    [crankFan, crank],
    [couplerFan, coupler],
    [rockerFan, rocker],
  ];
  const moving = new Group();
  moving.add(
    crankFan,
    couplerFan,
    rockerFan,
    crank.object,
    coupler.object,
    rocker.object,
    pArm.object,
    pinA,
    pinB,
    pinP,
  );
  scene.add(moving);
  let linkage: SceneLinkage | null = null;
  let lastFitKey = '';

  const place = (dir: Vector3, dist: number) => {
    camera.position.copy(fit.centre).addScaledVector(dir, dist);
    target.copy(fit.centre);
  };
  const viewDistance = () => fit.radius / Math.sin(degToRad(FOV_DEG / 2));
  const updateOrtho = () => {
    const aspect = size.x / Math.max(1, size.y);
    const h = fit.radius * 1.05;
    ortho.left = -h * aspect;
    ortho.right = h * aspect;
    ortho.top = h;
    ortho.bottom = -h;
    ortho.updateProjectionMatrix();
  };
  const resetView = () => {
    perspective.zoom = 1;
    ortho.zoom = 1;
    perspective.updateProjectionMatrix();
    updateOrtho();
    place(viewDir, viewDistance());
    look();
    invalidate();
  };

  const buildFixed = (l: SceneLinkage) => {
    scene.remove(fixed);
    disposeTree(fixed);
    for (let i = lineMaterials.length - 1; i >= 0; i--) {
      if (!moving.children.some((c) => (c as Line2).material === lineMaterials[i])) lineMaterials.splice(i, 1);
    }
    fixed = new Group();
    fixedBuilds++;
    const r = l.pinRadius;
    pinA.scale.setScalar(r / 0.045);
    pinB.scale.setScalar(r / 0.045);
    pinP.scale.setScalar((0.9 * r) / 0.045);
    const add = (o: Object3D) => fixed.add(o);
    const addLine = (o: Line2 | LineSegments2 | Line | null) => {
      if (!o) return;
      if (o instanceof LineSegments2) track(o);
      add(o);
    };
    const q = quality;
    if (l.kind === 'spherical') {
      const sphereLook = {
        color: '#b8c9e0',
        transparent: true,
        // One side shows about as much of the sphere as two: a little more opaque.
        opacity: q.sphereTwoSided ? 0.2 : 0.28,
        depthWrite: false,
        side: q.sphereTwoSided ? DoubleSide : FrontSide,
      };
      const sphere = new Mesh(
        new SphereGeometry(1, ...q.sphereSegments),
        q.sphereShading === 'phong'
          ? new MeshPhongMaterial({ ...sphereLook, shininess: 10 })
          : new MeshLambertMaterial(sphereLook),
      );
      sphere.renderOrder = -1;
      add(sphere);
      // Three great circles, faint, for depth.
      for (const [u, w] of [
        [new Vector3(1, 0, 0), new Vector3(0, 1, 0)],
        [new Vector3(1, 0, 0), new Vector3(0, 0, 1)],
        [new Vector3(0, 1, 0), new Vector3(0, 0, 1)],
      ]) {
        const pts: number[] = [];
        for (let i = 0; i <= 96; i++) {
          const t = (TWO_PI * i) / 96;
          pts.push(...u.clone().multiplyScalar(Math.cos(t)).addScaledVector(w, Math.sin(t)).toArray());
        }
        addLine(fixedLine(q, COLORS.gridAxis, 1, pts, 0.7));
      }
    }
    // Ground: the axes (thin), the ground link (thick), a bearing on each axis.
    for (const ax of l.axes) {
      const from = v3(ax.from);
      const to = v3(ax.to);
      addLine(fixedLine(q, COLORS.ground, 1.5, [...from.toArray(), ...to.toArray()]));
      const b = bearing(r * 0.9, r * 3.2);
      orient(b, v3(ax.bearing), to.clone().sub(from));
      add(b);
    }
    // The ground link: a fat line, or in the lean look a ribbon like the moving links.
    lines = [...links, pArm];
    if (q.fatMovingLines) {
      const ground = track(fatLine(COLORS.ground, 4, 0.85));
      setLine(ground, l.ground);
      add(ground);
    } else if (l.ground.length >= 6) {
      const ground = movingLine(q, COLORS.ground, 4, l.ground.length / 3, 0.85);
      ground.points.set(l.ground);
      lines.push(ground);
      add(ground.object);
    }
    for (const p of l.groundPins) {
      const g = ball(COLORS.ground, r * 0.8);
      g.position.copy(v3(p));
      add(g);
    }
    if (l.curve.length) addLine(fixedSegments(q, l.curve, { color: COLORS.trace, widthPx: 2.5 }));
    for (const path of l.paths) {
      addLine(
        fixedSegments(q, path.segments, {
          color: path.color,
          widthPx: 1.5,
          opacity: 0.75,
          dash: [0.04 * l.radius, 0.03 * l.radius],
        }),
      );
    }
    // A floor below an RSSR, for depth.
    if (l.floorZ !== null) {
      const floor = new Mesh(
        new CylinderGeometry(l.radius * 1.05, l.radius * 1.05, 0.001, 64),
        new MeshBasicMaterial({ color: COLORS.groundFill, transparent: true, opacity: 0.6, depthWrite: false }),
      );
      floor.rotation.x = PI / 2;
      floor.position.set(l.centre.x, l.centre.y, l.floorZ);
      floor.renderOrder = -2;
      add(floor);
    }
    scene.add(fixed);
  };

  /** Takes a leaner look after slow frames: the buffer at the new pixel ratio, the fixed parts rebuilt. */
  function lower(next: RenderQuality): void {
    quality = next;
    env.onQuality(next, antialias);
    renderer.setPixelRatio(pixelRatio(false));
    renderer.setSize(size.x, size.y, false);
    if (linkage) buildFixed(linkage);
  }

  const api: SpatialScene = {
    setLinkage(l) {
      linkage = l;
      buildFixed(l);
      const b = sceneBounds(l);
      fit = { centre: v3(b.centre), radius: b.radius };
      viewDir = v3(l.viewDir);
      const key = `${l.kind}:${b.radius.toPrecision(3)}:${b.centre.x.toPrecision(3)},${b.centre.y.toPrecision(3)},${b.centre.z.toPrecision(3)}`;
      if (key !== lastFitKey) {
        lastFitKey = key;
        resetView();
      }
      invalidate();
    },
    setPose(p) {
      moving.visible = p !== null && linkage !== null;
      if (!p || !linkage) {
        invalidate();
        return;
      }
      // Every frame of Play: the links' buffers are rewritten in place, nothing is allocated.
      const l = linkage;
      const spherical = l.kind === 'spherical';
      const put = spherical ? arcPointsInto : chordPointsInto;
      put(crank.points, l.crankPivot, p.A, FAN_STEPS);
      put(coupler.points, p.A, p.B, FAN_STEPS);
      put(rocker.points, l.rockerPivot, p.B, FAN_STEPS);
      for (const m of links) m.commit();
      pArm.object.visible = spherical && p.P !== undefined;
      if (spherical && p.P) {
        arcPointsInto(pArm.points, p.A, p.P, FAN_STEPS);
        pArm.commit();
      }
      for (const [f, m] of fans) {
        if (spherical) setFan(f, m.points);
        else f.visible = false;
      }
      pinA.position.set(p.A.x, p.A.y, p.A.z);
      pinB.position.set(p.B.x, p.B.y, p.B.z);
      pinP.visible = p.P !== undefined;
      if (p.P) pinP.position.set(p.P.x, p.P.y, p.P.z);
      invalidate();
    },
    setProjection(p) {
      const next = p === 'orthographic' ? ortho : perspective;
      if (next === camera) return;
      const dir = camera.position.clone().sub(target);
      next.position.copy(target).add(dir);
      next.zoom = camera.zoom;
      // Orthographic zoom has no distance: keep the framing by matching the perspective's distance to the fit.
      if (next === ortho) next.zoom = (viewDistance() / dir.length()) * perspective.zoom;
      else next.position.copy(target).addScaledVector(dir.normalize(), viewDistance() / ortho.zoom);
      if (next === perspective) next.zoom = 1;
      camera = next;
      updateOrtho();
      camera.updateProjectionMatrix();
      look();
      invalidate();
    },
    resetView,
    orbitBy(dAz, dEl) {
      const offset = camera.position.clone().sub(target);
      // Spherical coordinates about z (three's Spherical is about y: swap y and z).
      const s = new Spherical().setFromCartesianCoords(offset.x, offset.z, offset.y);
      s.theta += dAz;
      s.phi = Math.min(PI - 1e-3, Math.max(1e-3, s.phi - dEl));
      const v = new Vector3().setFromSpherical(s);
      camera.position.copy(target).add(new Vector3(v.x, v.z, v.y));
      look();
      invalidate();
    },
    zoomBy(f) {
      if (camera === perspective) {
        const offset = camera.position.clone().sub(target).divideScalar(f);
        camera.position.copy(target).add(offset);
      } else {
        ortho.zoom *= f;
        ortho.updateProjectionMatrix();
      }
      look();
      invalidate();
    },
    panBy(dx, dy) {
      const dist = camera.position.distanceTo(target);
      const h = camera === perspective ? 2 * dist * Math.tan(degToRad(FOV_DEG / 2)) : (2 * fit.radius) / ortho.zoom;
      const right = new Vector3().setFromMatrixColumn(camera.matrix, 0).multiplyScalar(dx * h);
      const up = new Vector3().setFromMatrixColumn(camera.matrix, 1).multiplyScalar(dy * h);
      const shift = right.add(up).negate();
      camera.position.add(shift);
      target.add(shift);
      look();
      invalidate();
    },
    resize(w, h, ratio) {
      if (ratio !== undefined) devicePixelRatio = ratio;
      const wPx = Math.max(1, Math.round(w));
      const hPx = Math.max(1, Math.round(h));
      renderer.setSize(wPx, hPx, false);
      size = new Vector2(wPx, hPx);
      for (const m of lineMaterials) m.resolution.copy(size);
      perspective.aspect = wPx / hPx;
      perspective.updateProjectionMatrix();
      updateOrtho();
      render();
    },
    async pngBytes(scale) {
      const ratio = renderer.getPixelRatio();
      renderer.setPixelRatio(scale);
      renderer.setSize(size.x, size.y, false);
      renderer.render(scene, camera);
      const blob =
        'convertToBlob' in canvas
          ? await canvas.convertToBlob({ type: 'image/png' })
          : await new Promise<Blob | null>((resolve) => canvas.toBlob(resolve, 'image/png'));
      renderer.setPixelRatio(ratio);
      renderer.setSize(size.x, size.y, false);
      render();
      if (!blob) throw new Error('could not encode the 3D view as PNG');
      return new Uint8Array(await blob.arrayBuffer());
    },
    frames: () => frameCount,
    dispose() {
      if (pending) cancelAnimationFrame(pending);
      clearTimeout(restTimer);
      layer.dispose();
      disposeTree(scene);
      renderer.dispose();
    },
  };
  return api;
}
