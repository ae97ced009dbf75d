import AxeBuilder from '@axe-core/playwright';
import { expect, test } from '@playwright/test';
import type { Page } from '@playwright/test';
import { waitReady } from './helpers';

/** axe's violations on the page, one line each (rule, impact, first target), for a readable failure. */
async function violations(page: Page): Promise<string[]> {
  const result = await new AxeBuilder({ page }).analyze();
  return result.violations.map(
    (v) => `${v.id} (${v.impact}): ${v.nodes.length} node(s), e.g. ${v.nodes[0]?.target.join(' ')}`,
  );
}

test.describe('accessibility', () => {
  test('the simulator has no axe violations', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    expect(await violations(page)).toEqual([]);
  });

  test('the solver lab has no axe violations', async ({ page }) => {
    await page.goto('./?page=lab');
    await expect(page.getByRole('img', { name: /Work-precision diagram/ })).toBeVisible({ timeout: 30_000 });
    expect(await violations(page)).toEqual([]);
  });

  test('the embed has no axe violations', async ({ page }) => {
    await page.goto('./embed.html?panels=controls,info,plots,export');
    await waitReady(page);
    expect(await violations(page)).toEqual([]);
  });

  test('a skip link is the first Tab stop and moves focus to the main content', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    await page.keyboard.press('Tab');
    const skip = page.getByRole('link', { name: 'Skip to main content' });
    await expect(skip).toBeFocused();
    await expect(skip).toBeInViewport();
    await page.keyboard.press('Enter');
    await expect(page.getByRole('main')).toBeFocused();
    // The next Tab stop is inside the main content: the linkage canvas.
    await page.keyboard.press('Tab');
    await expect(page.getByRole('img', { name: /^Linkage view/ })).toBeFocused();
  });

  test('the page tabs follow the WAI-ARIA tabs pattern', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    const sim = page.getByRole('tab', { name: 'Simulator' });
    const lab = page.getByRole('tab', { name: 'Solver lab' });
    const syn = page.getByRole('tab', { name: 'Synthesis' });
    const mech = page.getByRole('tab', { name: 'Mechanisms' });
    const spatial = page.getByRole('tab', { name: 'Spatial' });
    // One Tab stop: the selected tab only.
    await expect(sim).toHaveAttribute('tabindex', '0');
    await expect(lab).toHaveAttribute('tabindex', '-1');
    // The tab panel is its own element inside the main landmark, labelled by the selected tab.
    const panel = page.getByRole('tabpanel', { name: 'Simulator' });
    await expect(panel).toBeVisible();
    await expect(page.getByRole('main').getByRole('tabpanel')).toHaveCount(1);
    await expect(page.locator('main[role]')).toHaveCount(0);
    await sim.focus();
    await page.keyboard.press('ArrowRight');
    await expect(lab).toBeFocused();
    await expect(lab).toHaveAttribute('aria-selected', 'true');
    await expect(page.getByRole('tabpanel', { name: 'Solver lab' })).toBeVisible();
    await page.keyboard.press('ArrowRight');
    await expect(syn).toBeFocused();
    await expect(syn).toHaveAttribute('aria-selected', 'true');
    await page.keyboard.press('ArrowRight');
    await expect(mech).toBeFocused();
    await expect(mech).toHaveAttribute('aria-selected', 'true');
    await page.keyboard.press('ArrowRight');
    await expect(spatial).toBeFocused();
    await expect(spatial).toHaveAttribute('aria-selected', 'true');
    await page.keyboard.press('ArrowRight');
    await expect(sim).toBeFocused();
    await expect(sim).toHaveAttribute('aria-selected', 'true');
    await page.keyboard.press('End');
    await expect(spatial).toBeFocused();
    await page.keyboard.press('Home');
    await expect(sim).toBeFocused();
    await expect(sim).toHaveAttribute('aria-selected', 'true');
    await expect(lab).toHaveAttribute('tabindex', '-1');
  });

  test('the canvas shows its controls while focused and turns the crank with the arrow keys', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    const canvas = page.getByRole('img', { name: /^Linkage view/ });
    const hint = page.getByText(/Keys: ← → turn the crank/);
    await expect(hint).toBeHidden();
    await canvas.focus();
    await expect(hint).toBeVisible();
    await expect(canvas).toHaveAccessibleDescription(/Drag A to turn the crank/);
    await page.keyboard.press('ArrowRight');
    await expect(page.getByRole('textbox', { name: /^θ2/ })).toHaveValue('46');
    await page.keyboard.press('Shift+ArrowLeft');
    await expect(page.getByRole('textbox', { name: /^θ2/ })).toHaveValue('36');
  });
});
