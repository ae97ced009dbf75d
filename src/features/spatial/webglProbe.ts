/** What the page's WebGL is: none (null), or the renderer's name (null where not exposed). */
export interface WebglFacts {
  rendererName: string | null;
}

/**
 * The page's WebGL renderer (UNMASKED_RENDERER_WEBGL where exposed, else RENDERER), read on a throwaway context whose
 * context is lost at once, so the view's own context (on the page or in its worker) can be made with the right
 * antialias; null when WebGL cannot start here.
 */
export function probeWebgl(): WebglFacts | null {
  const gl = document.createElement('canvas').getContext('webgl');
  if (!gl) return null;
  try {
    const info = gl.getExtension('WEBGL_debug_renderer_info');
    const name: unknown = gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER);
    return { rendererName: typeof name === 'string' ? name : null };
  } finally {
    gl.getExtension('WEBGL_lose_context')?.loseContext();
  }
}

/** Whether this browser can hand a canvas to a worker (Worker, OffscreenCanvas, transferControlToOffscreen). */
export function canTransferCanvas(): boolean {
  return (
    typeof Worker !== 'undefined' &&
    typeof OffscreenCanvas !== 'undefined' &&
    typeof HTMLCanvasElement !== 'undefined' &&
    'transferControlToOffscreen' in HTMLCanvasElement.prototype
  );
}
