import {
  DepthTexture,
  FramebufferTexture,
  Mesh,
  NoBlending,
  OrthographicCamera,
  PlaneGeometry,
  Scene,
  ShaderLib,
  ShaderMaterial,
  Vector4,
  WebGLRenderTarget,
} from 'three';
import type { Camera, Material, Object3D, WebGLRenderer } from 'three';

/**
 * The 3D view's fixed parts drawn once per view and reused while only the linkage moves (Play with the camera still;
 * fixedLayerPlan.ts says when). A frame is then a copy of the layer and the moving parts over it. Drawn in the usual
 * order, translucent fixed parts cover the moving parts behind them: the sphere (or an RSSR's floor) tints the links
 * and pins behind it, and the translucent lines (great circles, ground link, paths) lie over them. So the layer keeps,
 * besides the colour of the fixed parts as a full frame draws them, per pixel: the depth of the opaque fixed parts
 * (which hide the moving parts behind them), and for each of the two translucent kinds, surfaces (drawn without depth:
 * sphere, floor) and lines, its nearest one's colour, opacity and depth. The moving parts' shaders (their materials'
 * copies) test and blend against these as the GPU would have done, so a frame looks as it did within rounding; what
 * differs is the order of the translucent fans and lines (a fan behind a line now blends over it). Colours come from the
 * canvas (copied as drawn there, in the output colour space); depths and opacities from render targets. Used where the
 * lean look draws (a software WebGL), whose materials it knows; a frame it cannot draw is drawn in full by the caller.
 */
export interface FixedLayer {
  /** Draws the layer for the current camera and drawing buffer (the canvas then holds a stale picture). */
  build(parts: FixedLayerParts): boolean;
  /** Draws a frame: the layer, then the visible moving parts over it. */
  draw(parts: FixedLayerParts): void;
  dispose(): void;
}

/** The scene as the view holds it: its fixed parts' group (flat) and its moving parts' group. */
export interface FixedLayerParts {
  scene: Scene;
  camera: Camera;
  fixed: Object3D;
  moving: Object3D;
}

/** The moving parts' materials the layer can draw against (the lean look's). */
const KNOWN_MATERIALS = new Set(['MeshBasicMaterial', 'MeshPhongMaterial', 'MeshLambertMaterial']);

const DECLARATIONS = /* glsl */ `
uniform highp sampler2D fcOpaqueDepth;
uniform highp sampler2D fcSurfaceDepth;
uniform sampler2D fcSurfaceColour;
uniform sampler2D fcSurfaceAlpha;
uniform highp sampler2D fcLineDepth;
uniform sampler2D fcLineColour;
uniform sampler2D fcLineAlpha;
`;

// Hidden by an opaque fixed part (the depth test three asks for is less-or-equal).
const HIDE = /* glsl */ `
  ivec2 fcPx = ivec2(gl_FragCoord.xy);
  if (gl_FragCoord.z > texelFetch(fcOpaqueDepth, fcPx, 0).x) discard;
`;

const LINE_OVER = /* glsl */ `
    gl_FragColor.rgb = mix(gl_FragColor.rgb, texelFetch(fcLineColour, fcPx, 0).rgb, texelFetch(fcLineAlpha, fcPx, 0).a);
`;

// After the output colour space, an opaque moving part: the surface in front of it, then the line, as the full
// frame's blending lays them over it.
const COVER = /* glsl */ `
  if (gl_FragCoord.z >= texelFetch(fcSurfaceDepth, fcPx, 0).x)
    gl_FragColor.rgb = mix(gl_FragColor.rgb, texelFetch(fcSurfaceColour, fcPx, 0).rgb, texelFetch(fcSurfaceAlpha, fcPx, 0).a);
  if (gl_FragCoord.z >= texelFetch(fcLineDepth, fcPx, 0).x) {${LINE_OVER}  }
`;

// A fan (drawn without depth, before the lines in the full frame): a line not hidden by an opaque fixed part lies over
// it whatever their depths. Blended over the layer, which holds the line already, the fan's colour mixed with the line
// by the line's opacity gives the full frame's result (line over fan over what is behind).
const FAN_COVER = /* glsl */ `
  float fcLine = texelFetch(fcLineDepth, fcPx, 0).x;
  if (fcLine < 1.0 && fcLine <= texelFetch(fcOpaqueDepth, fcPx, 0).x) {${LINE_OVER}  }
`;

const MAIN = 'void main() {';
const LAST = '#include <dithering_fragment>';

/**
 * The fragment shader (three's, before its includes are resolved) of a moving part's copy that draws on the layer: the
 * layer's textures declared, the test against the opaque fixed parts first, and after the last step (the output colour
 * space, dithering) the surface and line over an opaque part, or the line over a fan. Null when the shader lacks
 * either place (a three.js whose shaders changed): the layer is then not used.
 */
export function layerFragmentShader(source: string, fan: boolean): string | null {
  if (!source.includes(MAIN) || !source.includes(LAST)) return null;
  return source.replace(MAIN, `${DECLARATIONS}\n${MAIN}\n${HIDE}`).replace(LAST, `${LAST}\n${fan ? FAN_COVER : COVER}`);
}

/** The shader libraries of KNOWN_MATERIALS, in order. */
const KNOWN_SHADERS = ['basic', 'phong', 'lambert'] as const;

/** The moving parts' drawing on the layer: w × h device pixels of colour, opacity and depth. */
class Targets {
  readonly colour: FramebufferTexture;
  readonly surfaceColour: FramebufferTexture;
  readonly lineColour: FramebufferTexture;
  readonly opaque: WebGLRenderTarget;
  readonly surface: WebGLRenderTarget;
  readonly line: WebGLRenderTarget;
  constructor(
    readonly widthPx: number,
    readonly heightPx: number,
  ) {
    this.colour = new FramebufferTexture(widthPx, heightPx);
    this.surfaceColour = new FramebufferTexture(widthPx, heightPx);
    this.lineColour = new FramebufferTexture(widthPx, heightPx);
    const target = () =>
      new WebGLRenderTarget(widthPx, heightPx, { depthTexture: new DepthTexture(widthPx, heightPx) });
    this.opaque = target();
    this.surface = target();
    this.line = target();
  }
  dispose(): void {
    for (const t of [this.colour, this.surfaceColour, this.lineColour]) t.dispose();
    for (const t of [this.opaque, this.surface, this.line]) {
      t.depthTexture?.dispose();
      t.dispose();
    }
  }
}

type Kind = 'opaque' | 'surface' | 'line';

function kindOf(o: Object3D): Kind {
  const m = (o as Mesh).material as Material | undefined;
  if (!m || !m.transparent) return 'opaque';
  return m.depthWrite ? 'line' : 'surface';
}

/** Makes the layer for renderer (the view's): its targets follow the drawing buffer's size. */
export function createFixedLayer(renderer: WebGLRenderer): FixedLayer {
  let targets: Targets | null = null;
  const uniforms = {
    fcOpaqueDepth: { value: null as DepthTexture | null },
    fcSurfaceDepth: { value: null as DepthTexture | null },
    fcSurfaceColour: { value: null as FramebufferTexture | null },
    fcSurfaceAlpha: { value: null as WebGLRenderTarget['texture'] | null },
    fcLineDepth: { value: null as DepthTexture | null },
    fcLineColour: { value: null as FramebufferTexture | null },
    fcLineAlpha: { value: null as WebGLRenderTarget['texture'] | null },
  };
  const shadersFit = KNOWN_SHADERS.every(
    (k) =>
      layerFragmentShader(ShaderLib[k].fragmentShader, false) && layerFragmentShader(ShaderLib[k].fragmentShader, true),
  );
  /** Each moving material's copy that draws on the layer. */
  const copies = new Map<Material, Material>();
  const copyOf = (m: Material): Material => {
    let c = copies.get(m);
    if (c) return c;
    c = m.clone();
    // A translucent moving part (a fan) is drawn in the full frame after the surface and before the lines.
    const fan = m.transparent;
    c.onBeforeCompile = (shader) => {
      Object.assign(shader.uniforms, uniforms);
      shader.fragmentShader = layerFragmentShader(shader.fragmentShader, fan) ?? shader.fragmentShader;
    };
    c.customProgramCacheKey = () => `fixedLayer:${fan ? 'fan' : 'opaque'}`;
    copies.set(m, c);
    return c;
  };

  const blitScene = new Scene();
  const blitCamera = new OrthographicCamera(-1, 1, 1, -1, 0, 1);
  const blit = new ShaderMaterial({
    uniforms: { map: { value: null as FramebufferTexture | null } },
    vertexShader: 'void main() { gl_Position = vec4(position.xy, 0.0, 1.0); }',
    fragmentShader:
      'uniform sampler2D map;\nvoid main() { gl_FragColor = texelFetch(map, ivec2(gl_FragCoord.xy), 0); }',
    depthTest: false,
    depthWrite: false,
  });
  const quad = new Mesh(new PlaneGeometry(2, 2), blit);
  quad.frustumCulled = false;
  blitScene.add(quad);

  /**
   * Back to the canvas at the viewport its frames use: three rounds the canvas' viewport in setViewport but floors it
   * in setRenderTarget(null), a pixel apart on an odd CSS size at half resolution, which would shift the whole frame.
   */
  const viewport = new Vector4();
  const toCanvas = () => {
    renderer.setRenderTarget(null);
    renderer.setViewport(renderer.getViewport(viewport));
  };

  /** Draws the fixed parts of one kind, unblended and writing depth, into target and, given colour, the canvas. */
  const drawKind = (p: FixedLayerParts, kind: Kind, target: WebGLRenderTarget, colour: FramebufferTexture | null) => {
    const shown = p.fixed.children.map((c) => c.visible);
    const saved: [Material, Material['blending'], boolean][] = [];
    p.fixed.children.forEach((c, i) => {
      c.visible = shown[i] && kindOf(c) === kind;
      const m = (c as Mesh).material as Material | undefined;
      if (c.visible && m && kind !== 'opaque') {
        saved.push([m, m.blending, m.depthWrite]);
        m.blending = NoBlending;
        m.depthWrite = true;
      }
    });
    try {
      if (colour) {
        toCanvas();
        renderer.render(p.scene, p.camera);
        renderer.copyFramebufferToTexture(colour);
      }
      renderer.setRenderTarget(target);
      renderer.render(p.scene, p.camera);
    } finally {
      toCanvas();
      for (const [m, blending, depthWrite] of saved) {
        m.blending = blending;
        m.depthWrite = depthWrite;
      }
      p.fixed.children.forEach((c, i) => (c.visible = shown[i]));
    }
  };

  /** The moving meshes whose materials the layer knows; null when one is not (the frame is then drawn in full). */
  const movingMeshes = (p: FixedLayerParts): Mesh[] | null => {
    const out: Mesh[] = [];
    let known = true;
    p.moving.traverse((o) => {
      const m = o as Mesh;
      if (!m.isMesh) return;
      if (Array.isArray(m.material) || !KNOWN_MATERIALS.has(m.material.type)) known = false;
      else out.push(m);
    });
    return known ? out : null;
  };

  return {
    build(p) {
      if (!shadersFit || !movingMeshes(p)) return false;
      const gl = renderer.getContext();
      const { width, height } = gl.canvas;
      if (!targets || targets.widthPx !== width || targets.heightPx !== height) {
        targets?.dispose();
        targets = new Targets(width, height);
      }
      const t = targets;
      // The targets see the scene through the canvas' own viewport, so their pixels are the canvas' pixels.
      toCanvas();
      renderer.getCurrentViewport(viewport);
      for (const target of [t.opaque, t.surface, t.line]) target.viewport.copy(viewport);
      const movingShown = p.moving.visible;
      p.moving.visible = false;
      try {
        renderer.render(p.scene, p.camera);
        renderer.copyFramebufferToTexture(t.colour);
        drawKind(p, 'opaque', t.opaque, null);
        drawKind(p, 'surface', t.surface, t.surfaceColour);
        drawKind(p, 'line', t.line, t.lineColour);
      } finally {
        p.moving.visible = movingShown;
      }
      if (gl.getError() !== gl.NO_ERROR) return false;
      blit.uniforms.map.value = t.colour;
      uniforms.fcOpaqueDepth.value = t.opaque.depthTexture;
      uniforms.fcSurfaceDepth.value = t.surface.depthTexture;
      uniforms.fcSurfaceColour.value = t.surfaceColour;
      uniforms.fcSurfaceAlpha.value = t.surface.texture;
      uniforms.fcLineDepth.value = t.line.depthTexture;
      uniforms.fcLineColour.value = t.lineColour;
      uniforms.fcLineAlpha.value = t.line.texture;
      return true;
    },
    draw(p) {
      const meshes = movingMeshes(p) ?? [];
      toCanvas();
      const own = meshes.map((m) => m.material as Material);
      meshes.forEach((m, i) => (m.material = copyOf(own[i])));
      const fixedShown = p.fixed.visible;
      p.fixed.visible = false;
      const autoClear = renderer.autoClear;
      renderer.autoClear = false;
      try {
        // The copy covers every pixel: only the depth is cleared.
        renderer.clear(false, true, false);
        renderer.render(blitScene, blitCamera);
        renderer.render(p.scene, p.camera);
      } finally {
        renderer.autoClear = autoClear;
        p.fixed.visible = fixedShown;
        meshes.forEach((m, i) => (m.material = own[i]));
      }
    },
    dispose() {
      targets?.dispose();
      targets = null;
      for (const c of copies.values()) c.dispose();
      copies.clear();
      blit.dispose();
      quad.geometry.dispose();
    },
  };
}
