import { expect, test } from '@playwright/test';
import type { Locator } from '@playwright/test';
import { waitReady } from './helpers';

/** Sends one input event per value to a field or slider in a single task, as a scripted drag or an IME can. */
async function burst(target: Locator, values: readonly string[]): Promise<void> {
  await target.evaluate((el: HTMLInputElement, vs: readonly string[]) => {
    const setValue = Object.getOwnPropertyDescriptor(HTMLInputElement.prototype, 'value')!.set!;
    for (const v of vs) {
      setValue.call(el, v);
      el.dispatchEvent(new Event('input', { bubbles: true }));
    }
  }, values);
}

// 200 values of r3 between 3 and 5.45; the last is 5.45, so P + Q = r3 + r4 = 10.45 at the end.
const VALUES = Array.from({ length: 200 }, (_, i) => (3 + (i % 50) * 0.05).toFixed(2));

test.describe('a burst of 200 input events', () => {
  for (const role of ['slider', 'textbox'] as const) {
    test(`on the r3 ${role} throws nothing and ends on the last value`, async ({ page }) => {
      const errors: string[] = [];
      page.on('pageerror', (e) => errors.push(e.message));
      await page.goto('./');
      await waitReady(page);
      await burst(page.getByRole(role, { name: /^r3/ }), VALUES);
      await expect(page.getByRole('textbox', { name: /^r3/ })).toHaveValue('5.45');
      await expect(page.getByTestId('grashof-sums')).toContainText('P + Q = 10.45');
      expect(errors).toEqual([]);
    });
  }
});
