import { expect, test } from '@playwright/test';
import type { Page } from '@playwright/test';
import { ORIGIN, waitReady } from './helpers';

// A course page whose script talks to the widget through the postMessage API. The frame is sandboxed without
// allow-same-origin, so it is cross-origin to the page: only messages can cross.
const HOST = `${ORIGIN}/e2e-course/messages.html`;
const SRC = `${ORIGIN}/embed.html?r1=6&r2=2&r3=5&r4=5&t2=45&panels=controls&lock=r1`;

interface StateMessage {
  source: string;
  type: string;
  state: Record<string, unknown>;
}

/** The state events the host page has received from its frame, oldest first. */
function events(page: Page): Promise<StateMessage[]> {
  return page.evaluate(() => (window as unknown as { events: StateMessage[] }).events);
}

test.describe('the embed generator', () => {
  test('offers size presets, panels and locks, a scaled live preview and a snippet with title, fullscreen, lazy', async ({
    page,
  }) => {
    await page.goto('./');
    await waitReady(page);
    await expect(page.locator('.embed-preview')).toHaveCount(0); // lazy: nothing until opened
    await page.getByText('Embed generator: size, panels, locks, preview').click();
    const code = page.getByRole('textbox', { name: 'Embed code' });
    await expect(code).toHaveValue(/width="760" height="520"/);
    await page.getByRole('radio', { name: 'Compact 600×450' }).check();
    await page.getByRole('checkbox', { name: 'r3', exact: true }).check();
    await page.getByRole('checkbox', { name: 'Analysis' }).check();
    const snippet = await code.inputValue();
    expect(snippet).toMatch(/^<iframe src="http:\/\/localhost:\d+\/embed\.html\?r1=6&amp;/);
    for (const part of [
      'title="Four-bar linkage simulator"',
      'loading="lazy"',
      'allow="fullscreen"',
      'sandbox="allow-scripts',
      'width="600" height="450"',
      'panels=controls%2Cinfo%2Cplots',
      'lock=r3',
    ])
      expect(snippet).toContain(part);
    const preview = page.locator('.embed-preview iframe');
    await expect(preview).toHaveAttribute('width', '600');
    await expect(preview).toHaveAttribute('src', /lock=r3/);
    // Scaled to the panel: the frame's box on screen is narrower than 600 px and keeps the 600:450 aspect.
    const box = await preview.boundingBox();
    if (!box) throw new Error('no preview box');
    expect(box.width).toBeLessThan(600);
    expect(box.height / box.width).toBeCloseTo(450 / 600, 2);
    const frame = page.frameLocator('.embed-preview iframe');
    await waitReady(frame);
    await expect(frame.getByRole('textbox', { name: /^r3/ })).toBeDisabled();
    await page.getByRole('radio', { name: 'Responsive (fills the column)' }).check();
    await expect(code).toHaveValue(/^<div style="position:relative;width:100%;max-width:760px;aspect-ratio:760\/520;/);
    await expect(code).toHaveValue(/style="position:absolute;inset:0;width:100%;height:100%;border:0"/);
  });
});

test.describe('the embed generator in its column', () => {
  test('shows every size whole, keeps the preview out of the Tab order, and logs no sandbox warning', async ({
    page,
  }) => {
    const warnings: string[] = [];
    page.on('console', (m) => {
      if (/sandbox/i.test(m.text())) warnings.push(m.text());
    });
    await page.goto('./');
    await waitReady(page);
    await page.getByText('Embed generator: size, panels, locks, preview').click();
    const preview = page.frameLocator('.embed-preview iframe');
    await waitReady(preview);
    // Each size choice lies inside the generator's column, so none is cut off or out of reach.
    const column = await page.locator('.embed-generator').boundingBox();
    if (!column) throw new Error('no generator box');
    for (const name of ['Compact 600×450', 'Standard 760×520', 'Large 900×640', 'Responsive (fills the column)']) {
      const radio = page.getByRole('radio', { name, exact: true });
      const label = await page.locator('.segmented-item', { has: radio }).boundingBox();
      if (!label) throw new Error(`no box for ${name}`);
      expect(label.x, name).toBeGreaterThanOrEqual(column.x - 0.5);
      expect(label.x + label.width, name).toBeLessThanOrEqual(column.x + column.width + 0.5);
      await radio.check();
      await expect(radio).toBeChecked();
    }
    // From the last lock, one Tab goes past the preview to the embed code.
    await page.getByRole('checkbox', { name: 'Play', exact: true }).focus();
    await page.keyboard.press('Tab');
    await expect(page.getByRole('textbox', { name: 'Embed code' })).toBeFocused();
    expect(warnings).toEqual([]);
  });
});

test.describe('the postMessage API', () => {
  test('posts state events to the parent and takes set-state only from it, refusing locked values', async ({
    page,
  }) => {
    await page.route(HOST, (route) =>
      route.fulfill({
        contentType: 'text/html',
        body: `<!doctype html><html><head><title>Messages</title></head><body>
<iframe id="sim" title="Four-bar linkage simulator" sandbox="allow-scripts" src="${SRC}" width="760" height="520"></iframe>
<script>
  window.events = [];
  const frame = document.getElementById('sim');
  window.addEventListener('message', (e) => {
    if (e.source === frame.contentWindow && e.data && e.data.source === 'fourbar-lab') window.events.push(e.data);
  });
  window.send = (state) => frame.contentWindow.postMessage({ target: 'fourbar-lab', type: 'set-state', state }, '*');
</script></body></html>`,
      }),
    );
    await page.goto(HOST);
    const frame = page.frameLocator('#sim');
    await waitReady(frame);
    await expect.poll(async () => (await events(page)).at(-1)?.state.r3).toBe(5);
    expect((await events(page))[0]).toMatchObject({
      source: 'fourbar-lab',
      type: 'state',
      state: { t2: 45, br: 'open' },
    });

    await page.evaluate(() => (window as unknown as { send: (s: object) => void }).send({ r3: 4.5, r1: 9, t2: 90 }));
    await expect.poll(async () => (await events(page)).at(-1)?.state.t2).toBe(90);
    expect((await events(page)).at(-1)?.state).toMatchObject({ r1: 6, r3: 4.5, br: 'open' });
    await expect(frame.getByRole('img', { name: /^Linkage view\. θ2 90\.00°/ })).toBeVisible();

    // A command from anyone but the parent (here the frame itself) is ignored. The probe listener is added
    // after the widget's, so when it hears the command the widget has already handled it.
    const inner = page.frame({ url: /embed\.html/ });
    if (!inner) throw new Error('no embed frame');
    await inner.evaluate(
      () =>
        new Promise<void>((resolve) => {
          window.addEventListener('message', () => resolve(), { once: true });
          window.postMessage({ target: 'fourbar-lab', type: 'set-state', state: { r3: 3 } }, '*');
        }),
    );
    // Bad values and unknown keys are refused, nothing is evaluated; a valid branch in the same command applies.
    await page.evaluate(() =>
      (window as unknown as { send: (s: object) => void }).send({ r2: 'alert(1)', zz: 1, br: 'crossed' }),
    );
    await expect.poll(async () => (await events(page)).at(-1)?.state.br).toBe('crossed');
    expect((await events(page)).at(-1)?.state).toMatchObject({ r2: 2, r3: 4.5 });
  });
});
