import { expect, test } from '@playwright/test';
import { waitReady } from './helpers';

// The smaller defects of issue 11 that live in the controls and the analysis panel.
test.describe('controls and analysis details', () => {
  test('a typed speed of 0,75 shows on the slider as 0.75', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    await page.getByRole('textbox', { name: /^Speed/ }).fill('0,75');
    await expect(page.getByRole('slider', { name: /^Speed/ })).toHaveValue('0.75');
  });

  test('θ2 shows two decimals at most after Play', async ({ page }) => {
    await page.goto('./?spd=0.55');
    await waitReady(page);
    const theta2 = page.getByRole('textbox', { name: /^θ2/ });
    await page.getByRole('button', { name: 'Play' }).click();
    await expect.poll(async () => Number(await theta2.inputValue()), { timeout: 5000 }).toBeGreaterThan(46);
    await page.getByRole('button', { name: 'Pause' }).click();
    await expect(page.getByRole('button', { name: 'Play' })).toBeVisible();
    expect(await theta2.inputValue()).toMatch(/^\d+(\.\d{1,2})?$/);
  });

  test('the θ2 slider turns by whole degrees around the circle, and End is 359°, not 0°', async ({ page }) => {
    await page.goto('./?t2=202.98804');
    await waitReady(page);
    const theta2 = page.getByRole('textbox', { name: /^θ2/ });
    await page.getByRole('slider', { name: /^θ2/ }).focus();
    await page.keyboard.press('ArrowRight');
    await expect(theta2).toHaveValue('203');
    await page.keyboard.press('End');
    await expect(theta2).toHaveValue('359');
    await page.keyboard.press('ArrowRight');
    await expect(theta2).toHaveValue('0');
    await page.keyboard.press('PageDown');
    await expect(theta2).toHaveValue('350');
  });

  test('Step from an angle between two steps lands on the step grid', async ({ page }) => {
    await page.goto('./?t2=202.98804');
    await waitReady(page);
    await page.getByRole('button', { name: 'Step forward' }).click();
    await expect(page.getByRole('textbox', { name: /^θ2/ })).toHaveValue('203');
    await page.getByRole('button', { name: 'Step back' }).click();
    await expect(page.getByRole('textbox', { name: /^θ2/ })).toHaveValue('202');
  });

  test('a linkage that assembles nowhere says so: no μ, no Play, no exports', async ({ page }) => {
    await page.goto('./?r1=13&r2=2&r3=5&r4=5');
    await waitReady(page);
    await expect(page.getByTestId('design-cannot-assemble')).toHaveText(
      'This linkage cannot be assembled at any input angle',
    );
    await expect(page.getByTestId('design-mu-min')).toHaveText('—');
    await expect(page.getByTestId('design-mu-min-at')).toHaveCount(0);
    await expect(page.getByRole('button', { name: 'Play' })).toBeDisabled();
    for (const name of ['Export linkage view PNG', 'Export cycle CSV', 'Export animation GIF'])
      await expect(page.getByRole('button', { name })).toBeDisabled();
    // A length that makes it assemble again turns everything back on.
    await page.getByRole('textbox', { name: /^r1/ }).fill('6');
    await expect(page.getByRole('button', { name: 'Play' })).toBeEnabled();
    await expect(page.getByRole('button', { name: 'Export cycle CSV' })).toBeEnabled();
    await expect(page.getByTestId('design-cannot-assemble')).toHaveCount(0);
  });

  test('frames per cycle out of range says so as it is typed, and the animation waits for a good number', async ({
    page,
  }) => {
    await page.goto('./');
    await waitReady(page);
    const frames = page.getByRole('spinbutton', { name: 'Frames per cycle' });
    const gif = page.getByRole('button', { name: 'Export animation GIF' });
    for (const bad of ['0', '100000', '2.5']) {
      await frames.fill(bad);
      await expect(
        page.getByRole('alert').filter({ hasText: 'Frames per cycle must be a whole number' }),
      ).toBeVisible();
      await expect(frames).toHaveAttribute('aria-invalid', 'true');
      await expect(gif).toBeDisabled();
    }
    await frames.fill('90');
    await expect(page.getByText('Frames per cycle must be a whole number')).toHaveCount(0);
    await expect(gif).toBeEnabled();
  });

  test('choosing Crossed keeps the preset named', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    const preset = page.getByRole('combobox', { name: 'Preset' });
    await expect(preset).toHaveValue('report');
    await page.getByRole('radio', { name: 'Crossed' }).check();
    await expect.poll(() => new URL(page.url()).searchParams.get('br')).toBe('crossed');
    await expect(preset).toHaveValue('report');
  });

  test('the reachable range reads in the slider convention and the Grashof line never reads 5 < 5', async ({
    page,
  }) => {
    await page.goto('./?r1=4&r2=3&r3=3.5&r4=3');
    await waitReady(page);
    await expect(page.getByText('224.05° through 0° to 135.95°')).toBeVisible();
    await page.goto('./?r1=4&r2=1&r3=2&r4=3.0000001');
    await waitReady(page);
    await expect(page.getByTestId('grashof-sums')).toHaveText('S + L = 5 < P + Q = 5.0000001');
  });

  test('a 400-character bad number is echoed shortened', async ({ page }) => {
    await page.goto('./');
    await waitReady(page);
    const junk = `${'9'.repeat(400)}x`;
    await page.getByRole('textbox', { name: /^r2/ }).fill(junk);
    const alert = page.getByRole('alert').filter({ hasText: /^r2:/ });
    await expect(alert).toContainText(`“${'9'.repeat(23)}…”`);
    expect((await alert.textContent())?.length ?? 0).toBeLessThan(120);
  });

  test('locked embed fields are read-only and say so', async ({ page }) => {
    await page.goto('./embed.html?lock=r1,theta2,branch');
    await waitReady(page);
    const r1 = page.getByRole('textbox', { name: /^r1/ });
    await expect(r1).toHaveAttribute('readonly', '');
    await expect(r1).toHaveAttribute('aria-readonly', 'true');
    await expect(r1).toBeDisabled();
    await expect(page.getByRole('textbox', { name: /^r1 .*\(locked\)$/ })).toHaveCount(1);
    await expect(page.locator('.numctl.is-locked')).toHaveCount(2);
    await expect(page.getByRole('group', { name: /Branch \(locked\)/ })).toHaveClass(/is-locked/);
    await expect(page.getByRole('radio', { name: 'Crossed' })).toBeDisabled();
    await expect(page.getByRole('textbox', { name: /^r2/ })).toBeEditable();
  });

  test('the finished lab says so on its progress bar', async ({ page }) => {
    await page.goto('./?page=lab&lstep=5');
    await expect(page.getByTestId('solver-lab')).toHaveAttribute('data-ready', 'true', { timeout: 90_000 });
    await expect(page.getByRole('progressbar')).toHaveAttribute('aria-valuetext', 'Finished (100%)');
  });
});
