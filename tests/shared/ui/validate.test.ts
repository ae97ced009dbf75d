import { describe, expect, it } from 'vitest';
import { messagesEn } from '../../../src/shared/i18n/messagesEn';
import { messagesZhTw } from '../../../src/shared/i18n/messagesZhTw';
import { ECHO_MAX_CHARS, checkValue, parseField, readNumberText } from '../../../src/shared/ui/validateNumber';

function message(field: Parameters<typeof parseField>[0], raw: string): string {
  const r = parseField(field, raw);
  if (r.ok) throw new Error(`expected ${raw} to be rejected`);
  return messagesEn.fieldError(r.error, { raw: raw.trim(), min: String(r.error.min), max: String(r.error.max) });
}

describe('parseField', () => {
  it('accepts a positive length', () => {
    expect(parseField('r2', '2.5')).toEqual({ ok: true, value: 2.5 });
    expect(parseField('r1', '1e-7')).toEqual({ ok: true, value: 1e-7 });
    expect(parseField('r1', '1e7')).toEqual({ ok: true, value: 1e7 });
  });
  it('names the field and the value for empty, text, zero, negative and 1e308', () => {
    expect(message('r2', '')).toBe('r2: enter a number.');
    expect(message('r2', 'abc')).toBe('r2: “abc” is not a number.');
    expect(message('r3', '0')).toBe('r3 must be greater than 0, got 0.');
    expect(message('r4', '-1')).toBe('r4 must not be negative, got -1.');
    expect(message('r1', '1e308')).toContain('r1: 1e308 is out of range');
    expect(message('r1', '1e-320')).toContain('r1: 1e-320 is too small');
    expect(parseField('r1', '1e-12')).toEqual({ ok: true, value: 1e-12 });
  });
  it('rejects an absurd angle but takes negative ones', () => {
    expect(parseField('theta2', '-30')).toEqual({ ok: true, value: -30 });
    expect(parseField('theta2', '1e308').ok).toBe(false);
  });
  it('allows a coupler point on the crank pin (distance 0) but not a negative distance', () => {
    expect(parseField('couplerDistance', '0')).toEqual({ ok: true, value: 0 });
    expect(parseField('couplerDistance', '-1').ok).toBe(false);
  });
  it('names the speed range for 0, a negative or a too-small speed, never "greater than 0"', () => {
    for (const raw of ['0', '-1', '0.25', '11'])
      expect(message('speed', raw), raw).toBe(`Speed: ${raw} is out of range (0.5 to 10).`);
  });

  it('keeps the speed within 0.5 to 10 degrees per frame', () => {
    expect(parseField('speed', '10').ok).toBe(true);
    expect(parseField('speed', '11').ok).toBe(false);
    expect(parseField('speed', '0.25').ok).toBe(false);
  });
  it('has a message in Traditional Chinese that names the field and value too', () => {
    const r = parseField('r2', 'abc');
    if (r.ok) throw new Error('expected a rejection');
    expect(messagesZhTw.fieldError(r.error, { raw: 'abc', min: '1e-9', max: '1e9' })).toBe('r2：「abc」不是數字。');
  });
});

describe('checkValue', () => {
  it('rejects NaN and infinities from sliders or URLs', () => {
    expect(checkValue('r1', Number.NaN).ok).toBe(false);
    expect(checkValue('r1', Infinity).ok).toBe(false);
  });
});

describe('the rate and band fields', () => {
  it('take signed input rates within ±1e6 rad/s and ±1e9 rad/s², zero included', () => {
    expect(parseField('omega2', '-3.5')).toEqual({ ok: true, value: -3.5 });
    expect(parseField('omega2', '0')).toEqual({ ok: true, value: 0 });
    expect(parseField('omega2', '1000001').ok).toBe(false);
    expect(parseField('alpha2', '-1e9').ok).toBe(true);
    expect(parseField('alpha2', '2e9').ok).toBe(false);
  });
  it('keep the transmission band edges within 0° to 180°', () => {
    expect(parseField('muBandLo', '0').ok).toBe(true);
    expect(parseField('muBandHi', '180').ok).toBe(true);
    expect(parseField('muBandLo', '-1').ok).toBe(false);
    expect(parseField('muBandHi', '180.1').ok).toBe(false);
  });
});

describe('readNumberText', () => {
  const atMost = (max: number) => (v: number) => (v <= max ? null : `at most ${max}`);

  it('reads a decimal as parseDecimal does (comma, full-width digits), -0 as 0', () => {
    expect(readNumberText(' 2,5 ')).toEqual({ kind: 'number', value: 2.5 });
    expect(readNumberText('－３')).toEqual({ kind: 'number', value: -3 });
    const zero = readNumberText('-0');
    expect(zero).toEqual({ kind: 'number', value: 0 });
    expect(zero.kind === 'number' && Object.is(zero.value, -0)).toBe(false);
  });

  it('refuses a text that is not a number with no reason, echoing it trimmed', () => {
    expect(readNumberText(' 1..3 ')).toEqual({ kind: 'refused', text: '1..3', why: null });
    // 1e999 matches the decimal pattern but is Infinity: not a number a field can keep.
    expect(readNumberText('1e999')).toEqual({ kind: 'refused', text: '1e999', why: null });
  });

  it("refuses a number the check refuses, with the check's reason", () => {
    expect(readNumberText('7', { check: atMost(5) })).toEqual({ kind: 'refused', text: '7', why: 'at most 5' });
    expect(readNumberText('5', { check: atMost(5) })).toEqual({ kind: 'number', value: 5 });
  });

  it('never asks the check about a text that is not a number', () => {
    const asked: number[] = [];
    readNumberText('abc', { check: (v) => (asked.push(v), null) });
    expect(asked).toEqual([]);
  });

  it('reads a blank text as empty only where empty is allowed', () => {
    expect(readNumberText('  ', { allowEmpty: true })).toEqual({ kind: 'empty' });
    expect(readNumberText('  ')).toEqual({ kind: 'refused', text: '', why: null });
  });

  it('cuts a long refused text to ECHO_MAX_CHARS characters with an ellipsis', () => {
    const r = readNumberText('x'.repeat(100));
    expect(r.kind === 'refused' && Array.from(r.text)).toHaveLength(ECHO_MAX_CHARS);
    expect(r.kind === 'refused' && r.text.endsWith('…')).toBe(true);
  });
});
