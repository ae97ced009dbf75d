import { expect, test } from '@playwright/test';
import { waitReady } from './helpers';

const SHARED =
  'r1=5&r2=1.5&r3=4.5&r4=4&t2=120.25&br=crossed&pd=3&pa=-20&play=0&spd=2.5&dir=cw&grid=0&ang=1&ghost=0&trace=1&nr=cold&plots=together&n=720&lang=en';

test.describe('share links', () => {
  test('restore the whole state from the URL and write it back unchanged', async ({ page }) => {
    await page.goto(`./?${SHARED}`);
    await waitReady(page);
    await expect(page.getByRole('textbox', { name: /^r1/ })).toHaveValue('5');
    await expect(page.getByRole('textbox', { name: /^r4/ })).toHaveValue('4');
    await expect(page.getByRole('textbox', { name: /^θ2/ })).toHaveValue('120.25');
    await expect(page.getByRole('radio', { name: 'Crossed' })).toBeChecked();
    await expect(page.getByRole('radio', { name: 'Clockwise', exact: true })).toBeChecked();
    await expect(page.getByRole('radio', { name: 'Cold start' })).toBeChecked();
    await expect(page.getByRole('radio', { name: 'Together' })).toBeChecked();
    await expect(page.getByRole('checkbox', { name: 'Grid' })).not.toBeChecked();
    await expect(page.getByRole('textbox', { name: /^Speed/ })).toHaveValue('2.5');
    await expect(page.getByRole('textbox', { name: /^P angle/ })).toHaveValue('-20');
    // The app rewrites the address bar from its state: every parameter comes back the same.
    await page.getByRole('checkbox', { name: 'Angle labels' }).click();
    await page.getByRole('checkbox', { name: 'Angle labels' }).click();
    await expect.poll(() => new URL(page.url()).searchParams.get('ang')).toBe('1');
    const written = new URL(page.url()).searchParams;
    for (const [k, v] of new URLSearchParams(SHARED)) expect(written.get(k), k).toBe(v);
  });

  test('round-trip: a changed state opens identically from its URL', async ({ page, context }) => {
    await page.goto('./');
    await waitReady(page);
    await page.getByRole('textbox', { name: /^r3/ }).fill('4.75');
    await page.getByRole('radio', { name: 'Crossed' }).check();
    await page.getByRole('textbox', { name: /^θ2/ }).fill('200');
    await expect.poll(() => new URL(page.url()).searchParams.get('t2')).toBe('200');
    const url = page.url();
    const other = await context.newPage();
    await other.goto(url);
    await waitReady(other);
    await expect(other.getByRole('textbox', { name: /^r3/ })).toHaveValue('4.75');
    await expect(other.getByRole('textbox', { name: /^θ2/ })).toHaveValue('200');
    await expect(other.getByRole('radio', { name: 'Crossed' })).toBeChecked();
    const a = await page.getByRole('img', { name: /^Linkage view/ }).getAttribute('aria-label');
    const b = await other.getByRole('img', { name: /^Linkage view/ }).getAttribute('aria-label');
    expect(b).toBe(a);
  });

  test('ignores a bad parameter with a console warning and uses the default', async ({ page }) => {
    const warnings: string[] = [];
    page.on('console', (m) => {
      if (m.type() === 'warning') warnings.push(m.text());
    });
    await page.goto('./?r1=abc&r2=2&t2=1e308');
    await waitReady(page);
    await expect(page.getByRole('textbox', { name: /^r1/ })).toHaveValue('6');
    await expect(page.getByRole('textbox', { name: /^θ2/ })).toHaveValue('45');
    expect(warnings.some((w) => w.includes('r1="abc"'))).toBe(true);
    expect(warnings.some((w) => w.includes('t2="1e308"'))).toBe(true);
  });

  test('names the ignored key in a dismissible notice and keeps the default value', async ({ page }) => {
    await page.goto('./?r3=abc');
    await waitReady(page);
    const notice = page.getByTestId('url-notice');
    await expect(notice).toHaveAttribute('role', 'status');
    await expect(notice).toContainText('r3 = “abc”');
    await expect(page.getByRole('textbox', { name: /^r3/ })).toHaveValue('5');
    await notice.getByRole('button').click();
    await expect(page.getByTestId('url-notice')).toHaveCount(0);
  });

  for (const [width, height] of [
    [1280, 800],
    [390, 844],
  ] as const) {
    test(`at ${width}x${height} the notice is a card over the page that leaves Play and the canvas's joints free`, async ({
      page,
    }) => {
      await page.setViewportSize({ width, height });
      await page.goto('./?r3=abc');
      await waitReady(page);
      const notice = await page.getByTestId('url-notice').boundingBox();
      const play = await page.getByRole('button', { name: 'Play' }).boundingBox();
      expect(notice).not.toBeNull();
      expect(play).not.toBeNull();
      if (!notice || !play) return;
      // Inside the screen, not a line of bare text in the page's flow.
      expect(notice.x).toBeGreaterThanOrEqual(0);
      expect(notice.x + notice.width).toBeLessThanOrEqual(width);
      expect(notice.y + notice.height).toBeLessThanOrEqual(height);
      expect(await page.getByTestId('url-notice').evaluate((e) => getComputedStyle(e).position)).toBe('fixed');
      const apart = (a: typeof notice, b: typeof notice) =>
        a.x + a.width <= b.x || b.x + b.width <= a.x || a.y + a.height <= b.y || b.y + b.height <= a.y;
      expect(apart(notice, play)).toBe(true);
      // The crank pin A, where a student grabs the linkage.
      const [ax, ay] = ((await page.locator('canvas.linkage-canvas').getAttribute('data-a')) ?? '')
        .split(',')
        .map(Number);
      const canvasBox = await page.locator('canvas.linkage-canvas').boundingBox();
      expect(canvasBox).not.toBeNull();
      if (!canvasBox) return;
      expect(apart(notice, { x: canvasBox.x + ax - 8, y: canvasBox.y + ay - 8, width: 16, height: 16 })).toBe(true);
    });
  }

  test('shows no notice for a clean link', async ({ page }) => {
    await page.goto('./?r3=4.5');
    await waitReady(page);
    await expect(page.getByRole('textbox', { name: /^r3/ })).toHaveValue('4.5');
    await expect(page.getByTestId('url-notice')).toHaveCount(0);
  });
});
