import { ShaderLib } from 'three';
import { describe, expect, it } from 'vitest';
import { layerFragmentShader } from '../../../src/features/spatial/fixedLayer';

/** The shader libraries of the moving parts' materials in the lean look (MeshBasic, MeshPhong, MeshLambert). */
const LIBRARIES = ['basic', 'phong', 'lambert'] as const;

describe('layerFragmentShader', () => {
  it.each(LIBRARIES)("fits three's %s shader: the layer's textures declared, the opaque test first in main", (k) => {
    for (const fan of [false, true]) {
      const out = layerFragmentShader(ShaderLib[k].fragmentShader, fan);
      expect(out, `fan ${fan}`).not.toBeNull();
      const main = out!.indexOf('void main() {');
      expect(out!.indexOf('uniform highp sampler2D fcOpaqueDepth;')).toBeLessThan(main);
      // A part behind an opaque fixed part is dropped before anything else (three's depth test: less or equal).
      expect(out!.slice(main).replace(/\s+/g, ' ')).toMatch(
        /^void main\(\) \{ ivec2 fcPx = ivec2\(gl_FragCoord\.xy\); if \(gl_FragCoord\.z > texelFetch\(fcOpaqueDepth, fcPx, 0\)\.x\) discard;/,
      );
    }
  });

  it.each(LIBRARIES)(
    "%s: covers after the shader's last step (the output colour space, as the blending of the canvas sees it)",
    (k) => {
      for (const fan of [false, true]) {
        const out = layerFragmentShader(ShaderLib[k].fragmentShader, fan)!;
        const lastInclude = out.lastIndexOf('#include <');
        expect(out.indexOf('#include <colorspace_fragment>')).toBeGreaterThan(0);
        expect(out.indexOf('texelFetch(fcLineColour, fcPx, 0)'), `fan ${fan}`).toBeGreaterThan(lastInclude);
      }
    },
  );

  it('tints an opaque part by the surface in front of it; a fan, drawn after the surface, gets the line only', () => {
    const opaque = layerFragmentShader(ShaderLib.basic.fragmentShader, false)!;
    const fan = layerFragmentShader(ShaderLib.basic.fragmentShader, true)!;
    expect(opaque).toContain('if (gl_FragCoord.z >= texelFetch(fcSurfaceDepth, fcPx, 0).x)');
    expect(opaque).toContain('if (gl_FragCoord.z >= texelFetch(fcLineDepth, fcPx, 0).x)');
    expect(fan).not.toContain('texelFetch(fcSurfaceColour');
    // The line lies over a fan wherever it is drawn and not hidden by an opaque fixed part, whatever their depths.
    expect(fan).toContain('if (fcLine < 1.0 && fcLine <= texelFetch(fcOpaqueDepth, fcPx, 0).x)');
  });

  it('gives null for a shader without the places it writes to (the layer is then not used)', () => {
    expect(layerFragmentShader('void main() { gl_FragColor = vec4(1.0); }', false)).toBeNull();
    expect(layerFragmentShader('#include <dithering_fragment>', true)).toBeNull();
  });
});
