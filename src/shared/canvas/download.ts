import type { CycleTable } from '../csv';
import { cycleToCsv } from '../csv';

/** Saves a blob through a real browser download with the given file name. */
export function downloadBlob(blob: Blob, fileName: string): void {
  const url = URL.createObjectURL(blob);
  const a = document.createElement('a');
  a.href = url;
  a.download = fileName;
  a.rel = 'noopener';
  a.style.display = 'none';
  document.body.appendChild(a);
  a.click();
  a.remove();
  // Revoke later: some browsers read the URL after click() returns.
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}

/** PNG bytes of a canvas; rejects when the canvas cannot be encoded (tainted, too large). */
export function canvasToPngBytes(canvas: HTMLCanvasElement): Promise<Uint8Array> {
  return new Promise((resolve, reject) => {
    canvas.toBlob((blob) => {
      if (!blob) {
        reject(new Error(`could not encode a ${canvas.width}x${canvas.height} canvas as PNG`));
        return;
      }
      blob.arrayBuffer().then((b) => resolve(new Uint8Array(b)), reject);
    }, 'image/png');
  });
}

/** Downloads PNG bytes under fileName. */
export function downloadPng(bytes: Uint8Array, fileName: string): void {
  downloadBlob(new Blob([bytes as BlobPart], { type: 'image/png' }), fileName);
}

/** Downloads the cycle as CSV (d3-dsv formatting) under fileName. */
export function downloadCsv(table: CycleTable, fileName: string): void {
  downloadBlob(new Blob([cycleToCsv(table)], { type: 'text/csv;charset=utf-8' }), fileName);
}

/** Downloads text (CSV) under fileName with the given MIME type. */
export function downloadText(text: string, fileName: string, type: string): void {
  downloadBlob(new Blob([text], { type }), fileName);
}
