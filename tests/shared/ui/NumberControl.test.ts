import { createElement } from 'react';
import { renderToStaticMarkup } from 'react-dom/server';
import { describe, expect, it } from 'vitest';
import { NumberControl } from '../../../src/shared/ui/NumberControl';
import { THETA2_DECIMALS } from '../../../src/shared/format';

const noop = () => undefined;

/** The rendered text field's attributes, from static markup. */
function field(html: string): string {
  const m = /<input[^>]*class="numctl-field"[^>]*>/.exec(html);
  if (!m) throw new Error('no text field');
  return m[0];
}

describe('NumberControl', () => {
  it('shows θ2 to the field precision after Play', () => {
    const html = renderToStaticMarkup(
      createElement(NumberControl, {
        field: 'theta2',
        value: 255.045227,
        decimals: THETA2_DECIMALS,
        min: 0,
        max: 360,
        step: 0.5,
        onCommit: noop,
      }),
    );
    expect(field(html)).toContain('value="255.05"');
  });

  it('renders a locked field read-only, announced as locked, with the slider disabled', () => {
    const html = renderToStaticMarkup(
      createElement(NumberControl, {
        field: 'r1',
        value: 6,
        min: 0.01,
        max: 20,
        step: 0.01,
        onCommit: noop,
        locked: true,
      }),
    );
    expect(html).toContain('class="numctl is-locked"');
    const f = field(html);
    expect(f).toMatch(/readonly=""/i); // HTML attribute names are case-insensitive; React 18 writes readonly
    expect(f).toContain('aria-readonly="true"');
    expect(f).toContain('aria-disabled="true"');
    expect(html).toMatch(/<input[^>]*type="range"[^>]*disabled=""/);
    expect(html).toContain('<span class="sr-only"> (locked)</span>');
  });

  it('renders an unlocked field editable', () => {
    const html = renderToStaticMarkup(
      createElement(NumberControl, { field: 'r1', value: 6, min: 0.01, max: 20, step: 0.01, onCommit: noop }),
    );
    expect(field(html)).not.toMatch(/readonly/i);
    expect(html).not.toContain('is-locked');
  });
});
