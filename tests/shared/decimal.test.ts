import Decimal from 'decimal.js';
import { describe, expect, it } from 'vitest';
import { normalizeNumberText, parseDecimal, plainDecimal } from '../../src/shared/decimal';
import { createRandom } from '../../src/synthesis/random';

describe('plainDecimal', () => {
  it('reads plain and exponent decimals, a leading sign and surrounding white space', () => {
    expect(plainDecimal('2.5')).toBe(2.5);
    expect(plainDecimal(' -1e-7 ')).toBe(-1e-7);
    expect(plainDecimal('+.5')).toBe(0.5);
    expect(plainDecimal('5.')).toBe(5);
    expect(plainDecimal('1E+3')).toBe(1000);
  });

  it('refuses hex, Infinity, words, separators, commas, empty text and a sign alone', () => {
    const bad = [
      '0x10',
      'Infinity',
      '-Infinity',
      'NaN',
      'abc',
      '1,000.5',
      '2,5',
      '1e',
      'e5',
      '--1',
      '+-1',
      '',
      ' ',
      '-',
      '.',
      '1 2',
      '1_000',
      '１',
    ];
    for (const s of bad) expect(plainDecimal(s), s).toBeNaN();
  });

  it('gives Number’s value, ±Infinity past the largest double (a range check then refuses it by name)', () => {
    expect(plainDecimal('1e999')).toBe(Infinity);
    expect(plainDecimal('-1e999')).toBe(-Infinity);
  });

  it('reads every decimal as decimal.js does, to the nearest double (seeded property)', () => {
    const random = createRandom(28);
    const digits = (n: number) => Array.from({ length: n }, () => Math.floor(random() * 10)).join('');
    for (let i = 0; i < 2000; i++) {
      const sign = ['', '-', '+'][Math.floor(random() * 3)];
      const whole = digits(Math.floor(random() * 6));
      const fraction = random() < 0.6 ? `.${digits(Math.floor(random() * 12))}` : '';
      const mantissa =
        whole === '' && (fraction === '' || fraction === '.') ? `${whole}0${fraction}` : `${whole}${fraction}`;
      const exponent =
        random() < 0.4
          ? `${random() < 0.5 ? 'e' : 'E'}${['', '-', '+'][Math.floor(random() * 3)]}${digits(1 + Math.floor(random() * 2))}`
          : '';
      const text = `${sign}${mantissa}${exponent}`;
      // decimal.js parses the exact decimal and rounds once to the nearest double (toNumber): the oracle.
      expect(plainDecimal(text), text).toBe(new Decimal(text.replace(/^\+/, '')).toNumber());
    }
  });
});

describe('parseDecimal', () => {
  it('reads what a person types: a decimal comma, full-width digits and signs, the minus sign', () => {
    expect(parseDecimal('2,5')).toBe(2.5);
    expect(normalizeNumberText('２．５')).toBe('2.5');
    expect(parseDecimal('－３')).toBe(-3);
    expect(parseDecimal('\u22122.5')).toBe(-2.5);
    expect(parseDecimal(' -1e-7 ')).toBe(-1e-7);
  });

  it('refuses what plainDecimal refuses, and a comma beside a point or two commas', () => {
    for (const s of ['0x10', 'Infinity', 'abc', '1,000.5', '1,000,000', '1e', '--1', ''])
      expect(parseDecimal(s), s).toBeNaN();
  });
});
