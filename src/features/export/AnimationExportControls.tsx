import './AnimationExportControls.css';
import { useEffect, useId, useRef, useState } from 'react';
// The planner's bounds and types only: the encoders load on the first export.
import { FRAMES_PER_CYCLE_DEFAULT, FRAMES_PER_CYCLE_MAX, FRAMES_PER_CYCLE_MIN } from './animation/framesPerCycle';
import type { AnimationSize } from './animation/exportSize';
import type { AnimationExportResult, AnimationFormat } from './animation/types';
import type { AnimationRequest } from './animationExporter';
import { useMessages } from '../../shared/i18n/MessagesContext';
import { Segmented } from '../../shared/ui/Segmented';
import { Toggle } from '../../shared/ui/Toggle';

const FRAMES_PER_CYCLE = { min: FRAMES_PER_CYCLE_MIN, max: FRAMES_PER_CYCLE_MAX, initial: FRAMES_PER_CYCLE_DEFAULT };

/** Props of AnimationExportControls: the export itself (useExports' onAnimation). */
export interface AnimationExportControlsProps {
  onAnimation: (request: AnimationRequest) => Promise<AnimationExportResult>;
  /** Nothing to animate (a linkage that assembles nowhere): the buttons are disabled; default false. */
  blocked?: boolean;
}

/** Frames per cycle typed in the field, or null when it is not a whole number from 36 to 720. */
export function parseFramesPerCycle(text: string): number | null {
  const n = Number(text.trim());
  if (text.trim() === '' || !Number.isInteger(n) || n < FRAMES_PER_CYCLE.min || n > FRAMES_PER_CYCLE.max) return null;
  return n;
}

interface Running {
  done: number;
  total: number;
}

/** The animation's settings as the panel holds them: the size, the typed frames per cycle and the loop. */
interface AnimationSettings {
  size: AnimationSize;
  framesText: string;
  loop: boolean;
}

/**
 * One animation export at a time: start runs it (refusing frames out of range), cancel stops it; running is its
 * progress and status how the last one ended. Leaving the panel (or the page) stops an export still drawing frames.
 */
function useAnimationRun(onAnimation: AnimationExportControlsProps['onAnimation']) {
  const t = useMessages();
  const [running, setRunning] = useState<Running | null>(null);
  const [status, setStatus] = useState('');
  const abort = useRef<AbortController | null>(null);
  useEffect(() => () => abort.current?.abort(), []);

  const start = (format: AnimationFormat, { size, framesText, loop }: AnimationSettings) => {
    const framesPerCycle = parseFramesPerCycle(framesText);
    if (framesPerCycle === null) {
      setStatus(t.framesOutOfRange(FRAMES_PER_CYCLE.min, FRAMES_PER_CYCLE.max));
      return;
    }
    const ac = new AbortController();
    abort.current = ac;
    setRunning({ done: 0, total: framesPerCycle });
    setStatus('');
    onAnimation({
      format,
      size,
      framesPerCycle,
      loop,
      signal: ac.signal,
      onProgress: (p) => setRunning({ done: p.framesDone, total: p.frameCount }),
    })
      .then((r) => {
        if (r.status === 'done') setStatus(t.animationDone(format.toUpperCase()));
        else if (r.status === 'cancelled') setStatus(t.animationCancelled);
        else setStatus(t.animationUnsupported(r.reason));
      })
      .catch((e: unknown) => setStatus(t.exportFailed(e instanceof Error ? e.message : String(e))))
      .finally(() => {
        if (abort.current === ac) abort.current = null;
        setRunning(null);
      });
  };
  return { running, status, start, cancel: () => abort.current?.abort() };
}

/**
 * The animation part of the Export panel: size (screen or 720p), frames per cycle, loop, the GIF and WebM
 * buttons, and while one runs a progress bar with Cancel; a status line says how it ended.
 */
export function AnimationExportControls({ onAnimation, blocked = false }: AnimationExportControlsProps) {
  const t = useMessages();
  const framesId = useId();
  const [size, setSize] = useState<AnimationSize>('screen');
  const [framesText, setFramesText] = useState(String(FRAMES_PER_CYCLE.initial));
  const [loop, setLoop] = useState(true);
  const { running, status, start: run, cancel } = useAnimationRun(onAnimation);
  const start = (format: AnimationFormat) => run(format, { size, framesText, loop });
  // The field says at once when its number is out of range, and the buttons wait for a good one.
  const framesBad = parseFramesPerCycle(framesText) === null;
  const errorId = `${framesId}-error`;
  const cannotStart = running !== null || blocked || framesBad;

  return (
    <div className="anim-export">
      <Segmented<AnimationSize>
        legend={t.animationSize}
        value={size}
        options={[
          { value: 'screen', label: t.sizeScreen },
          { value: '720p', label: t.size720p },
        ]}
        onChange={setSize}
        disabled={running !== null}
      />
      <div className="anim-export-row">
        <label className="anim-export-frames" htmlFor={framesId}>
          {t.framesPerCycle}
        </label>
        <input
          id={framesId}
          type="number"
          inputMode="numeric"
          min={FRAMES_PER_CYCLE.min}
          max={FRAMES_PER_CYCLE.max}
          step={1}
          value={framesText}
          disabled={running !== null}
          aria-invalid={framesBad ? true : undefined}
          aria-describedby={framesBad ? errorId : undefined}
          onChange={(e) => setFramesText(e.target.value)}
          className="anim-export-frames-input"
        />
        <Toggle label={t.animationLoop} checked={loop} onChange={setLoop} disabled={running !== null} />
      </div>
      {framesBad ? (
        <p id={errorId} className="numctl-error" role="alert">
          {t.framesOutOfRange(FRAMES_PER_CYCLE.min, FRAMES_PER_CYCLE.max)}
        </p>
      ) : null}
      <div className="export-buttons">
        <button type="button" className="btn btn-small" disabled={cannotStart} onClick={() => start('gif')}>
          {t.exportGif}
        </button>
        <button type="button" className="btn btn-small" disabled={cannotStart} onClick={() => start('webm')}>
          {t.exportWebm}
        </button>
      </div>
      {running ? (
        <div className="anim-export-row">
          <progress
            className="anim-export-progress"
            aria-label={t.animationProgress}
            max={running.total}
            value={running.done}
          />
          <button type="button" className="btn btn-small" onClick={cancel}>
            {t.cancel}
          </button>
        </div>
      ) : null}
      <p className="status-line" role="status" aria-live="polite">
        {running ? t.animationRunning(running.done, running.total) : status}
      </p>
    </div>
  );
}
