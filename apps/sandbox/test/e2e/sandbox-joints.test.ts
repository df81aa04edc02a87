import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { Browser, Page } from 'playwright-core';
import { join } from 'node:path';
import { JOINT_RGB } from '../../src/colors.js';
import { ARTIFACTS, colourfulPixels, launchBrowser, openPage, pixelsNear, stat } from './browser.js';

// The sandbox with joints: every joint scene steps and draws its joints in both renderers, the Cut
// tool destroys the joint clicked (and only it), and the Pin tool pins a body to the world where
// clicked, through one shared static anchor.

/** Small versions, so each loads quickly on a two-core machine. */
const JOINT_SCENES: Record<string, string> = {
  chain: 'links=20',
  bridge: 'planks=12&load=3',
  'joint-grid': 'size=12',
  ragdolls: 'count=4&columns=4',
  car: 'bumps=5',
  jellies: 'count=2&side=4',
  blobs: 'count=2',
};

let browser: Browser;

beforeAll(async () => {
  browser = await launchBrowser();
});

afterAll(async () => {
  await browser?.close();
});

async function stepsPass(page: Page, target: number): Promise<void> {
  await page.waitForFunction((t) => Number(document.getElementById('stat-steps')?.textContent?.replace(/\D/g, '')) >= t, target, { timeout: 30_000 });
}

const jointCount = (page: Page) => page.evaluate(() => window.__sandboxProbe!.jointCount());

/** Where on the page (CSS pixels) a world point is drawn. */
async function pageAt(page: Page, x: number, y: number): Promise<{ x: number; y: number }> {
  const at = await page.evaluate((p) => window.__sandboxProbe!.toCss(p.x, p.y), { x, y });
  const box = await page.locator('#overlay').boundingBox();
  return { x: box!.x + at.x, y: box!.y + at.y };
}

/** Waits for the monitor to show `n` joints: it refreshes a click at once, but it is text on a page. */
async function monitorShowsJoints(page: Page, n: number): Promise<void> {
  await page.waitForFunction((k) => Number(document.getElementById('stat-joints')?.textContent?.replace(/\D/g, '')) === k, n, { timeout: 10_000 });
}

describe('sandbox with joints', () => {
  it('every joint scene steps and draws its joints in canvas 2D and WebGL without console errors', async () => {
    for (const [scene, params] of Object.entries(JOINT_SCENES)) {
      for (const renderer of ['canvas', 'webgl']) {
        const { page, errors } = await openPage(browser, `/?scene=${scene}&renderer=${renderer}&${params}`);
        await stepsPass(page, 3);
        const label = `${scene} ${renderer}`;
        expect(await page.evaluate(() => window.__sandboxProbe!.route()), label).toBe('shapes');
        const joints = await jointCount(page);
        expect(joints, label).toBeGreaterThan(0);
        expect(await stat(page, 'joints'), label).toBe(joints);
        expect(await colourfulPixels(page), label).toBeGreaterThan(100);
        // The joints' own colour, which no body takes: lines and anchor dots on screen.
        expect(await pixelsNear(page, JOINT_RGB), label).toBeGreaterThan(10);
        if (scene === 'chain') await page.screenshot({ path: join(ARTIFACTS, `sandbox-chain-${renderer}.png`) });
        expect(errors, label).toEqual([]);
        await page.close();
      }
    }
  });

  it('scenes without joints show none of the joint colour', async () => {
    for (const renderer of ['canvas', 'webgl']) {
      const { page, errors } = await openPage(browser, `/?scene=pyramid&base=8&renderer=${renderer}`);
      await stepsPass(page, 3);
      expect(await jointCount(page)).toBe(0);
      expect(await page.locator('#row-joints').isHidden()).toBe(true);
      expect(await pixelsNear(page, JOINT_RGB), renderer).toBe(0);
      expect(errors).toEqual([]);
      await page.close();
    }
  });

  it('follows the car across as it drives, so it stays in the picture', async () => {
    const { page, errors } = await openPage(browser, '/?scene=car&bumps=5');
    await stepsPass(page, 2);
    const start = await page.evaluate(() => ({ car: window.__sandboxProbe!.pose(0), region: window.__sandboxProbe!.region() }));
    await stepsPass(page, 120);
    const later = await page.evaluate(() => ({ car: window.__sandboxProbe!.pose(0), region: window.__sandboxProbe!.region() }));
    // Two seconds at 10 rad/s on 0.4 m wheels is several metres: past the region's first third.
    expect(later.car.x - start.car.x).toBeGreaterThan(2);
    expect(later.region.x - start.region.x).toBeCloseTo(later.car.x - start.car.x, 0);
    expect(later.region.y).toBe(start.region.y);
    expect(errors).toEqual([]);
    await page.close();
  });

  it('the Cut tool destroys the joint clicked, only that one, and the chain below it falls', async () => {
    const { page, errors } = await openPage(browser, '/?scene=chain&links=10');
    await stepsPass(page, 5);
    await page.locator('#pause').click();
    await page.getByLabel('Tool').selectOption('cut');
    const before = await jointCount(page);
    expect(before).toBe(10);

    // A click well away from every joint cuts nothing.
    const region = await page.evaluate(() => window.__sandboxProbe!.region());
    const empty = await pageAt(page, region.x + region.width * 0.9, region.y + region.height * 0.1);
    await page.mouse.click(empty.x, empty.y);
    expect(await jointCount(page)).toBe(before);

    // Joint 5 pins link 5 to link 6 (body 6): cut there, half way down the chain.
    const joint = (await page.evaluate(() => window.__sandboxProbe!.joint(5)))!;
    const at = await pageAt(page, (joint.ax + joint.bx) / 2, (joint.ay + joint.by) / 2);
    const below0 = await page.evaluate(() => window.__sandboxProbe!.pose(10));
    const above0 = await page.evaluate(() => window.__sandboxProbe!.pose(3));
    await page.mouse.click(at.x, at.y);
    expect(await jointCount(page)).toBe(before - 1);
    await monitorShowsJoints(page, before - 1);
    const left: number[] = [];
    for (let k = 0; k < before - 1; k++) left.push((await page.evaluate((i) => window.__sandboxProbe!.joint(i), k))!.handle);
    expect(left).not.toContain(joint.handle);

    await page.locator('#pause').click();
    await stepsPass(page, (await stat(page, 'steps')) + 30);
    const below = await page.evaluate(() => window.__sandboxProbe!.pose(10));
    const above = await page.evaluate(() => window.__sandboxProbe!.pose(3));
    // Half a second of free fall is 1.25 m; the links still hanging from the pin stay put.
    expect(below.y - below0.y).toBeGreaterThan(0.5);
    expect(Math.abs(above.y - above0.y)).toBeLessThan(0.1);
    await page.screenshot({ path: join(ARTIFACTS, 'sandbox-chain-cut.png') });
    expect(errors).toEqual([]);
    await page.close();
  });

  it('the Pin tool pins a body to the world where clicked, both pins on one static anchor', async () => {
    const { page, errors } = await openPage(browser, '/?scene=bridge&planks=12&load=3');
    await stepsPass(page, 2);
    await page.locator('#pause').click();
    await page.getByLabel('Tool').selectOption('pin');
    const joints0 = await jointCount(page);
    const bodies0 = await stat(page, 'bodies');
    // Bodies 0 and 1 are the posts, 2..13 the planks, then the three boxes dropped, still in the air.
    const pinned = 14;
    const free = 15;
    const box0 = await page.evaluate((h) => window.__sandboxProbe!.pose(h), pinned);
    const free0 = await page.evaluate((h) => window.__sandboxProbe!.pose(h), free);

    // A click on nothing pins nothing.
    const region = await page.evaluate(() => window.__sandboxProbe!.region());
    const empty = await pageAt(page, region.x + region.width * 0.95, region.y + region.height * 0.05);
    await page.mouse.click(empty.x, empty.y);
    expect(await jointCount(page)).toBe(joints0);

    // Off the box's centre, so it hangs from a corner and turns.
    const pinX = box0.x + 0.25;
    const pinY = box0.y - 0.25;
    const at = await pageAt(page, pinX, pinY);
    await page.mouse.click(at.x, at.y);
    expect(await jointCount(page)).toBe(joints0 + 1);
    await monitorShowsJoints(page, joints0 + 1);
    // The static anchor pins hold to is a body of its own.
    expect(await stat(page, 'bodies')).toBe(bodies0 + 1);
    const pin = (await page.evaluate((k) => window.__sandboxProbe!.joint(k), joints0))!;
    expect(Math.hypot(pin.ax - pinX, pin.ay - pinY)).toBeLessThan(0.05);
    expect(Math.hypot(pin.bx - pinX, pin.by - pinY)).toBeLessThan(0.05);

    // A second pin reuses the anchor: one more joint, no more bodies.
    const third = await page.evaluate(() => window.__sandboxProbe!.pose(16));
    const at3 = await pageAt(page, third.x, third.y);
    await page.mouse.click(at3.x, at3.y);
    expect(await jointCount(page)).toBe(joints0 + 2);
    expect(await stat(page, 'bodies')).toBe(bodies0 + 1);

    await page.locator('#pause').click();
    await stepsPass(page, (await stat(page, 'steps')) + 60);
    const box = await page.evaluate((h) => window.__sandboxProbe!.pose(h), pinned);
    const fell = await page.evaluate((h) => window.__sandboxProbe!.pose(h), free);
    // The pinned box hangs where it was pinned (its centre within its half-diagonal of the pin),
    // the unpinned one fell to the bridge.
    expect(Math.hypot(box.x - pinX, box.y - pinY)).toBeLessThan(0.6);
    expect(fell.y - free0.y).toBeGreaterThan(1);
    const held = (await page.evaluate((k) => window.__sandboxProbe!.joint(k), joints0))!;
    expect(Math.hypot(held.bx - pinX, held.by - pinY)).toBeLessThan(0.05);
    await page.screenshot({ path: join(ARTIFACTS, 'sandbox-bridge-pin.png') });
    expect(errors).toEqual([]);
    await page.close();
  });

  it('a world that refuses joints is offered neither Pin nor Cut: a link asking for Pin gets Drag, and says why', async () => {
    const { page, errors } = await openPage(browser, '/?scene=uniform-polygons&n=50&tool=pin');
    await stepsPass(page, 2);
    const tool = page.getByLabel('Tool');
    expect(await tool.inputValue()).toBe('drag');
    await expect.poll(() => new URL(page.url()).searchParams.get('tool')).toBe(null);
    expect(await page.locator('#notice').innerText()).toMatch(/Pin makes a joint.*using Drag/);
    const disabled = () => tool.locator('option').evaluateAll((os) => (os as HTMLOptionElement[]).filter((o) => o.disabled).map((o) => o.value));
    expect(await disabled()).toEqual(['pin', 'cut']);
    // A scene with joints offers them again.
    await page.getByLabel('Scene').selectOption('chain');
    await expect.poll(disabled).toEqual([]);
    await tool.selectOption('pin');
    await expect.poll(() => new URL(page.url()).searchParams.get('tool')).toBe('pin');
    expect(errors).toEqual([]);
    await page.close();
  });
});
