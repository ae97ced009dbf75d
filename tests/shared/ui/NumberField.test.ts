import { createElement } from 'react';
import { renderToStaticMarkup } from 'react-dom/server';
import { describe, expect, it } from 'vitest';
import type { NumberFieldProps } from '../../../src/shared/ui/NumberField';
import { NumberField } from '../../../src/shared/ui/NumberField';

const noop = () => undefined;

/** The field rendered to static markup (no DOM: what the first paint shows, before any typing). */
function render(props: Partial<NumberFieldProps>): string {
  return renderToStaticMarkup(
    createElement(NumberField, { label: 'Gravity g', value: 9.81, onCommit: noop, errorText: () => '', ...props }),
  );
}

/** The text input's tag. */
function input(html: string): string {
  const m = /<input[^>]*>/.exec(html);
  if (!m) throw new Error('no input');
  return m[0];
}

describe('NumberField', () => {
  it('labels the input with the label and the unit, the unit shown beside the field but not read twice', () => {
    const html = render({ unit: 'm/s²' });
    const id = /<input[^>]*id="([^"]+)"/.exec(html)?.[1];
    expect(html).toContain(`<label for="${id}" class="num-field-label">Gravity g<span class="sr-only"> (m/s²)</span>`);
    expect(html).toContain('<span class="num-field-unit" aria-hidden="true">m/s²</span>');
  });

  it('keeps an empty place for an empty unit, and none without one', () => {
    expect(render({ unit: '' })).toContain('<span class="num-field-unit" aria-hidden="true"></span>');
    expect(render({ unit: '' })).not.toContain('sr-only');
    expect(render({})).not.toContain('num-field-unit');
  });

  it('shows the value to its decimals, valid at first, with the page class on the root', () => {
    const html = render({ value: 0.123456789, decimals: 6, className: 'frc-field' });
    expect(input(html)).toContain('value="0.123457"');
    expect(input(html)).not.toContain('aria-invalid');
    expect(html).not.toContain('role="alert"');
    expect(html).toMatch(/^<div class="num-field frc-field">/);
  });

  it('shows no value but the placeholder for null, and hides the label visually when asked', () => {
    const html = render({ value: null, placeholder: 'auto (4)', hideLabel: true });
    expect(input(html)).toContain('value=""');
    expect(input(html)).toContain('placeholder="auto (4)"');
    expect(html).toContain('class="sr-only">Gravity g</label>');
  });
});
