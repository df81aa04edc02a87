import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import type { Browser } from 'playwright-core';
import { launchBrowser, openPage, sandboxUrl } from './browser.js';

/**
 * The sandbox serves the API reference that `npm run docs:api` writes into public/api/ (the global
 * setup writes it before the server starts), linked from the sandbox's header, as `npm start` does.
 */
describe('the API reference in the sandbox', () => {
  let browser: Browser;

  beforeAll(async () => {
    browser = await launchBrowser();
  });

  afterAll(async () => {
    await browser?.close();
  });

  it('was generated before the server started', () => {
    expect(inject('apiReferenceError')).toBe('');
  });

  it("is one click from the sandbox's header, at /api/, and leads to World's page", async () => {
    const { page, errors } = await openPage(browser, '/', 'dev');
    const link = page.locator('header nav a', { hasText: 'API reference' });
    await expect(link.count()).resolves.toBe(1);
    await Promise.all([page.waitForURL(sandboxUrl('/api/', 'dev')), link.click()]);
    await expect(page.title()).resolves.toBe('maxgrid API reference');
    for (const name of ['@maxgrid/engine', '@maxgrid/scenes']) {
      await expect(page.locator('.col-content a', { hasText: name }).count(), name).resolves.toBeGreaterThan(0);
    }

    await page.locator('.col-content a', { hasText: '@maxgrid/engine' }).first().click();
    await page.locator('.col-content a', { hasText: /^World$/ }).first().click();
    await page.waitForURL(/\/api\/classes\/.*World\.html$/);
    await expect(page.locator('h1').innerText()).resolves.toContain('World');
    // The methods the README's examples call, each with its own section and summary.
    for (const id of ['createbox', 'createcircle', 'createjoint', 'step', 'getbody', 'startworkers', 'debugrender']) {
      const section = page.locator(`section.tsd-member:has(> h3#${id})`);
      await expect(section.count(), id).resolves.toBe(1);
      await expect(section.locator('.tsd-comment').first().innerText(), id).resolves.not.toBe('');
    }
    expect(errors).toEqual([]);
    await page.close();
  });

  it('answers /api without the slash with a redirect to it, so that the pages find their assets', async () => {
    const response = await fetch(sandboxUrl('/api', 'dev'), { redirect: 'manual' });
    expect(response.status).toBe(301);
    expect(response.headers.get('location')).toBe('/api/');
  });
});
