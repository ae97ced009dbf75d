import { describe, expect, it } from 'vitest';
import { LAB_METHODS, runWorkPrecision } from '../../../src/study/workPrecision';
import { solveClosedForm } from '../../../src/solver';
import { labProgressStatus, labStageText, parseLabStage } from '../../../src/features/lab/labStage';
import { messagesEn as appEn } from '../../../src/shared/i18n/messagesEn';
import { messagesZhTw as appZhTw } from '../../../src/shared/i18n/messagesZhTw';
import { labMessagesEn } from '../../../src/features/lab/labMessagesEn';
import { labMessagesZhTw } from '../../../src/features/lab/labMessagesZhTw';

/** Every UI string of a language: the app's and the solver lab's. */
const messagesEn = { ...appEn, ...labMessagesEn };
const messagesZhTw = { ...appZhTw, ...labMessagesZhTw };

/** Every stage text the lab reports on a coarse study (a fake clock keeps the timing passes short); run once. */
let cached: Promise<string[]> | null = null;
function reportedStages(): Promise<string[]> {
  cached ??= collectStages();
  return cached;
}

async function collectStages(): Promise<string[]> {
  const stages: string[] = [];
  let clock = 0;
  await runWorkPrecision(
    { r1: 6, r2: 2, r3: 5, r4: 5 },
    {
      branch: 'open',
      stepDeg: 90,
      now: () => (clock += 5),
      minTimeMs: 1,
      // The stages do not depend on the reference's accuracy: the closed form stands in for the 40-digit one.
      reference: (l, theta2, sigma) => {
        const p = solveClosedForm(l, theta2, sigma === 1 ? 'open' : 'crossed');
        return p ? { theta3: p.theta3, theta4: p.theta4 } : null;
      },
      onProgress: (_f, stage) => stages.push(stage),
    },
  );
  return stages;
}

describe('parseLabStage', () => {
  it('recognises every stage the lab reports', async () => {
    const stages = await reportedStages();
    expect(stages.length).toBeGreaterThan(10);
    for (const s of stages) expect(parseLabStage(s).kind, s).not.toBe('other');
    expect(new Set(stages.map((s) => parseLabStage(s).kind))).toEqual(
      new Set(['reference', 'solve', 'timing', 'done']),
    );
  });

  it('reads the method, the tolerance and the timing pass', () => {
    expect(parseLabStage('NR + predictor, tol 1e-9')).toEqual({ kind: 'solve', method: 'newton', tol: 1e-9 });
    expect(parseLabStage("Report's NR (seed)")).toEqual({ kind: 'solve', method: 'seed', tol: null });
    expect(parseLabStage('timing 2/3: NR, no predictor, tol 0.001')).toEqual({
      kind: 'timing',
      pass: 2,
      passes: 3,
      method: 'newton-no-predictor',
      tol: 0.001,
    });
    expect(parseLabStage('Closed form + NR polish')).toEqual({
      kind: 'solve',
      method: 'closed-form-polish',
      tol: null,
    });
    expect(parseLabStage('something new')).toEqual({ kind: 'other', text: 'something new' });
    expect(parseLabStage('')).toEqual({ kind: 'idle' });
  });
});

describe('labStageText', () => {
  it('shows no English words in zh-TW for any stage the lab reports', async () => {
    for (const s of await reportedStages()) {
      const zh = labStageText(parseLabStage(s), messagesZhTw);
      expect(zh, s).not.toBe('');
      // Method names are translated; only tolerances like 1e-9 keep Latin letters (single 'e').
      expect(zh, s).not.toMatch(/[A-Za-z]{2,}/);
    }
  });

  it('uses the translated method name and the tolerance', () => {
    const s = parseLabStage('timing 1/3: NR + predictor, tol 0.000001');
    expect(labStageText(s, messagesZhTw)).toBe('第 1/3 輪計時：牛頓法延續 + 預測，容許誤差 1e\u22126');
    expect(labStageText(s, messagesEn)).toBe('timing pass 1 of 3: NR continuation + predictor, tolerance 1e\u22126');
    for (const m of LAB_METHODS)
      expect(labStageText(parseLabStage(m.label), messagesZhTw)).toBe(messagesZhTw.methodNames[m.method]);
  });
});

describe('labProgressStatus', () => {
  const base = { running: false, progress: null, cancelled: false, error: null, hasResult: false };

  it('announces the running stage and percent', () => {
    const s = labProgressStatus(
      { ...base, running: true, progress: { fraction: 0.426, stage: 'reference' } },
      messagesZhTw,
    );
    expect(s).toEqual({ text: '執行中：40 位數參考解（43%）', percent: 43 });
  });

  it('says finished, not "Running (0%)", once the study is done', () => {
    const s = labProgressStatus({ ...base, hasResult: true }, messagesEn);
    expect(s).toEqual({ text: 'Finished (100%)', percent: 100 });
    expect(s.text).not.toMatch(/Running/);
    expect(labProgressStatus({ ...base, hasResult: true }, messagesZhTw).text).toBe('已完成（100%）');
  });

  it('says cancelled, failed or not run yet', () => {
    expect(labProgressStatus({ ...base, cancelled: true }, messagesEn)).toEqual({ text: 'Cancelled', percent: 0 });
    expect(labProgressStatus({ ...base, cancelled: true, hasResult: true }, messagesEn).text).toBe('Cancelled');
    expect(labProgressStatus({ ...base, error: 'boom', hasResult: true }, messagesEn).text).toBe('Failed');
    expect(labProgressStatus(base, messagesEn)).toEqual({ text: 'Not run yet', percent: 0 });
  });
});
