import type { Page } from '@playwright/test';
import { expect, test } from '@playwright/test';
import { artifact } from './helpers';

// The Function mode against the synthesis module's own oracle (docs/synthesis.md): y = log10 x on [1, 10], θ2 from
// 30° to 90°, θ4 from −60° to −150°, three Chebyshev points is exact there (1e-12 rad against the 60-digit oracle).

/** The three Chebyshev points of [1, 10], written out here: (x0 + x1)/2 − (x1 − x0)/2 · cos((2j − 1)π/6). */
const CHEBYSHEV = [1, 3, 5].map((k) => 5.5 - 4.5 * Math.cos((k * Math.PI) / 6));
/** Three exact pairs are solved to rounding: the error there is a few ulps of θ4 times y's range (1). */
const EXACT = 1e-9;

/** Waits for a design and returns the precision table's x and error per row (full precision, from data-*). */
async function precisionRows(page: Page): Promise<{ x: number; error: number }[]> {
  await expect(page.getByTestId('function-mode')).toHaveAttribute('data-ready', 'true');
  const rows = page.getByTestId('precision-table').locator('tbody tr');
  return rows.evaluateAll((trs) =>
    trs.map((tr) => ({ x: Number(tr.getAttribute('data-x')), error: Number(tr.getAttribute('data-error')) })),
  );
}

const field = (page: Page) => page.getByRole('textbox', { name: 'y = f(x)' });

test.describe('synthesis: function generation', () => {
  test('log10 on [1, 10] from the URL is exact at the Chebyshev points, which the error plot marks', async ({
    page,
  }) => {
    await page.goto('./?page=syn&syn=fn&fx=log10(x)&xr=1,10&t2r=30,90&t4r=-60,-150&np=3');
    const rows = await precisionRows(page);
    expect(rows).toHaveLength(3);
    rows.forEach((r, i) => {
      expect(r.x).toBeCloseTo(CHEBYSHEV[i], 12);
      expect(Math.abs(r.error)).toBeLessThan(EXACT);
    });
    // Largest error 0.0066 (docs/synthesis.md), no defects.
    const max = Number(await page.getByTestId('function-max-error').getAttribute('data-value'));
    expect(max).toBeGreaterThan(0.006);
    expect(max).toBeLessThan(0.007);
    await expect(page.getByTestId('function-defects')).toHaveText(/^No defects/);
    // The plot: the error curve and a dot per precision point.
    const chart = page.getByTestId('structural-error-chart');
    await expect(chart).toContainText('Structural error');
    await expect(chart.locator('circle')).toHaveCount(3);
    await page.screenshot({ path: artifact('synthesis-function-1280.png') });
  });

  test('typing log10(x) and three points by hand gives the same exact design', async ({ page }) => {
    await page.goto('./?page=syn&syn=fn&fx=sqrt(x)&np=5');
    await expect(page.getByTestId('precision-table').locator('tbody tr')).toHaveCount(5);
    await field(page).fill('log10(x)');
    await page.getByRole('textbox', { name: 'Precision points' }).fill('3');
    await expect(page.getByTestId('precision-table').locator('tbody tr')).toHaveCount(3);
    const rows = await precisionRows(page);
    rows.forEach((r, i) => {
      expect(r.x).toBeCloseTo(CHEBYSHEV[i], 12);
      expect(Math.abs(r.error)).toBeLessThan(EXACT);
    });
    // log10(x) and three points are the defaults: the link drops fx and np again.
    await expect(page).not.toHaveURL(/fx=|np=/);
  });

  test('more precision points are fitted by least squares: a smaller largest error, no longer exact', async ({
    page,
  }) => {
    await page.goto('./?page=syn&syn=fn&np=5');
    const rows = await precisionRows(page);
    expect(rows).toHaveLength(5);
    expect(Math.max(...rows.map((r) => Math.abs(r.error)))).toBeGreaterThan(1e-6);
    const max = Number(await page.getByTestId('function-max-error').getAttribute('data-value'));
    expect(max).toBeLessThan(0.006);
  });

  test('a bad expression gets a message naming it, and the last good one stays', async ({ page }) => {
    await page.goto('./?page=syn&syn=fn');
    await precisionRows(page);
    await field(page).fill('log10(');
    await expect(page.getByTestId('fx-error')).toHaveText(/^“log10\(” is not a formula of x: /);
    await expect(page.getByTestId('precision-table').locator('tbody tr')).toHaveCount(3);
    await field(page).fill('foo(x)');
    await expect(page.getByTestId('fx-error')).toHaveText(/^“foo\(x\)” is not a formula of x: “foo” is not a function/);
    await expect(page).not.toHaveURL(/fx=/);
  });

  test('JavaScript is refused, never run: constructor.constructor and __proto__', async ({ page }) => {
    const dialogs: string[] = [];
    page.on('dialog', (d) => {
      dialogs.push(d.message());
      void d.dismiss();
    });
    await page.goto('./?page=syn&syn=fn');
    await precisionRows(page);
    await field(page).fill('constructor.constructor("alert(1)")()');
    await expect(page.getByTestId('fx-error')).toHaveText(
      /^“constructor\.constructor\("alert\(1\)"\)\(\)” is not a formula/,
    );
    await field(page).fill('x.__proto__');
    await expect(page.getByTestId('fx-error')).toHaveText(
      '“x.__proto__” is not a formula of x: Property access (.) is not part of a formula.',
    );
    // From a link too: the URL key refuses the quotes, and the parser the property access.
    await page.goto(`./?page=syn&syn=fn&fx=${encodeURIComponent('x.constructor')}`);
    await expect(page.getByTestId('function-problem')).toHaveText(
      /^“x\.constructor” is not a formula of x: Property access/,
    );
    await page.goto(`./?page=syn&syn=fn&fx=${encodeURIComponent('constructor.constructor("alert(1)")()')}`);
    await expect(page.getByTestId('function-mode')).toHaveAttribute('data-ready', 'true');
    await expect(field(page)).toHaveValue('log10(x)');
    expect(dialogs).toEqual([]);
  });

  test('an x range where f has no value says so, naming the expression', async ({ page }) => {
    await page.goto('./?page=syn&syn=fn&xr=-1,10');
    await expect(page.getByTestId('function-problem')).toHaveText(/^“log10\(x\)” has no finite value at x = −1:/);
  });

  test('the expression parser loads only when Function mode is opened', async ({ page }) => {
    const chunks: string[] = [];
    page.on('request', (r) => {
      if (/\/expression-[^/]*\.js$/.test(r.url())) chunks.push(r.url());
    });
    await page.goto('./?page=syn&syn=motion');
    await expect(page.getByTestId('motion-mode')).toBeVisible();
    expect(chunks).toEqual([]);
    await page.getByRole('radio', { name: 'Function' }).check();
    await precisionRows(page);
    expect(chunks).toHaveLength(1);
  });

  test('Open in simulator carries the function generator', async ({ page }) => {
    await page.goto('./?page=syn&syn=fn');
    await precisionRows(page);
    await page.getByRole('button', { name: 'Open in simulator' }).click();
    await expect(page.getByRole('tab', { name: 'Simulator' })).toHaveAttribute('aria-selected', 'true');
    await expect.poll(() => new URL(page.url()).searchParams.get('r1')).toBe('1');
    expect(Number(new URL(page.url()).searchParams.get('t2'))).toBeCloseTo(30, 6);
  });
});

test.describe('synthesis: function generation in zh-TW and on a phone', () => {
  test('speaks zh-TW: 結構誤差 and 精確點', async ({ page }) => {
    await page.goto('./?page=syn&syn=fn&lang=zh-TW');
    await precisionRows(page);
    await expect(page.getByTestId('structural-error-chart')).toContainText('結構誤差');
    await expect(page.getByTestId('structural-error-chart')).toContainText('精確點');
    await expect(page.getByRole('heading', { name: '精確點' })).toBeVisible();
    await field(page).fill('log10(');
    await expect(page.getByTestId('fx-error')).toHaveText(/^「log10\(」不是 x 的算式/);
    await page.screenshot({ path: artifact('synthesis-function-zh-TW.png') });
  });

  test('works at 390×844: nothing overflows sideways and the fields answer the keyboard', async ({ browser }) => {
    const context = await browser.newContext({ viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true });
    const page = await context.newPage();
    await page.goto(`${test.info().project.use.baseURL}?page=syn&syn=fn`);
    await precisionRows(page);
    const overflow = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
    expect(overflow).toBeLessThanOrEqual(0);
    await page.getByRole('button', { name: 'Pause' }).click();
    const slider = page.getByRole('slider', { name: 'x', exact: true });
    await slider.focus();
    await page.keyboard.press('Home');
    await expect(page.getByText(/^x = 1: f\(x\) = 0,/)).toBeVisible();
    await page.screenshot({ path: artifact('synthesis-function-390.png'), fullPage: true });
    await context.close();
  });
});

test.describe('synthesis: function generation says what is wrong (issue 34, item 10)', () => {
  test('sin on [−2, 2]: not monotone and a large error, never a green "No defects"', async ({ page }) => {
    await page.goto('./?page=syn&syn=fn&fx=sin(x)&xr=-2,2');
    await precisionRows(page);
    const checks = page.getByTestId('function-defects');
    await expect(checks).not.toContainText('No defects');
    await expect(checks.locator('[data-defect="notMonotone"]')).toContainText(/turns back near x = −1\.5\d/);
    await expect(checks.locator('[data-defect="largeError"]')).toContainText(/over 5 %/);
    await page.screenshot({ path: artifact('synthesis-function-checks-1280.png') });
  });

  test('no real linkage: a plain message with a range to try, in zh-TW too', async ({ page }) => {
    await page.goto('./?page=syn&syn=fn&fx=exp(x)&xr=0,3');
    const problem = page.getByTestId('function-problem');
    await expect(problem).toHaveText(
      /^No real four-bar fits these ranges: the crank would have to point opposite to θ2\. Try θ[24] from −?\d+° to −?\d+°/,
    );
    await expect(problem).not.toHaveText(/\d{6,}|\(.*\(/);
    await page.goto('./?page=syn&syn=fn&fx=exp(x)&xr=0,3&lang=zh-TW');
    await expect(problem).toHaveText(/^沒有實際的四連桿符合這些範圍：曲柄必須指向 θ2 的反方向。請試試 θ[24] 從/);
    await expect(problem).not.toHaveText(/[A-Za-z]{2,}/);
    await page.screenshot({ path: artifact('synthesis-function-nolinkage-zh-TW.png') });
  });
});
