import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import * as engine from '../src/index.js';

const ROOT = fileURLToPath(new URL('../../..', import.meta.url));

/**
 * The TypeScript examples of a document, joined in order (later ones use what earlier ones made),
 * with their imports of '@maxgrid/engine' turned into parameters: the code the docs show, run.
 */
function examples(file: string): { names: string[]; body: string; blocks: number } {
  const text = readFileSync(`${ROOT}/${file}`, 'utf8');
  const blocks = [...text.matchAll(/```ts\n([\s\S]*?)```/g)].map((m) => m[1]);
  const names = new Set<string>();
  const body = blocks
    .join('\n')
    .replace(/^import \{([^}]*)\} from '@maxgrid\/engine';$/gm, (_line, list: string) => {
      for (const name of list.split(',')) names.add(name.trim());
      return '';
    });
  return { names: [...names], body, blocks: blocks.length };
}

const AsyncFunction = Object.getPrototypeOf(async () => {}).constructor as new (...args: string[]) => (...values: unknown[]) => Promise<void>;

describe('the examples in the docs run against the engine as written', () => {
  it.each(['README.md', 'docs/engine.md', 'packages/engine/README.md'])('%s', async (file) => {
    const { names, body, blocks } = examples(file);
    expect(blocks).toBeGreaterThan(0);
    expect(body).not.toMatch(/^import /m);
    const lines: unknown[][] = [];
    const quiet = { log: (...values: unknown[]) => lines.push(values) };
    const run = new AsyncFunction(...names, 'console', body);
    await run(...names.map((name) => (engine as Record<string, unknown>)[name]), quiet);
    for (const line of lines) for (const value of line) if (typeof value === 'number') expect(Number.isFinite(value)).toBe(true);
  });
});
