import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { Application, LogLevel, ReflectionKind, TSConfigReader, TypeDocReader, type ProjectReflection, type Reflection } from 'typedoc';

const CONFIG = fileURLToPath(new URL('../../../typedoc.json', import.meta.url));

// The methods a reader of the README reaches for first: if one drops out of the reference (made
// private, renamed, or its export lost), the page is no longer the engine's API.
const WORLD_MAIN_MEMBERS = [
  'createCircle',
  'createBox',
  'createPolygon',
  'createCapsule',
  'createBody',
  'createSegment',
  'createJoint',
  'step',
  'getBody',
  'getShape',
  'views',
  'startWorkers',
  'debugRender',
  'rayCast',
  'queryAABB',
  'stats',
];

const DECLARED =
  ReflectionKind.Class |
  ReflectionKind.Interface |
  ReflectionKind.TypeAlias |
  ReflectionKind.Enum |
  ReflectionKind.Variable |
  ReflectionKind.Function |
  ReflectionKind.Method |
  ReflectionKind.Accessor |
  ReflectionKind.Constructor |
  ReflectionKind.Property;

/** Members of an inline object type (SCENES' entries, a getter's `{ width, height }`) document as their owner does. */
function inTypeLiteral(reflection: Reflection): boolean {
  for (let r = reflection.parent; r; r = r.parent) if (r.kindOf(ReflectionKind.TypeLiteral)) return true;
  return false;
}

function documented(reflection: Reflection): boolean {
  if (reflection.hasComment()) return true;
  const r = reflection as Reflection & { signatures?: Reflection[]; getSignature?: Reflection; setSignature?: Reflection };
  return [...(r.signatures ?? []), r.getSignature, r.setSignature].some((s) => s?.hasComment() === true);
}

let out: string;
let project: ProjectReflection;
const problems: string[] = [];
let app: Application;

// The repository's own typedoc.json, as `npm run docs:api` runs it, into a scratch folder.
beforeAll(async () => {
  out = mkdtempSync(join(tmpdir(), 'maxgrid-api-'));
  app = await Application.bootstrapWithPlugins({ options: CONFIG, out }, [new TypeDocReader(), new TSConfigReader()]);
  const log = app.logger.log.bind(app.logger);
  app.logger.log = (message: string, level: LogLevel) => {
    if (level >= LogLevel.Warn) problems.push(message);
    log(message, level);
  };
  const converted = await app.convert();
  if (!converted) throw new Error(`typedoc could not convert the packages:\n${problems.join('\n')}`);
  project = converted;
  app.validate(project);
  await app.generateOutputs(project);
}, 60_000);

afterAll(() => {
  if (out) rmSync(out, { recursive: true, force: true });
});

describe('the API reference', () => {
  it('builds with typedoc.json, which fails on a referenced type left unexported or a broken link', () => {
    const validation = app.options.getValue('validation');
    expect(validation.notExported).toBe(true);
    // typedoc's own notExported check passes every type outside the root package; this runs it per workspace package.
    expect(app.options.getValue('plugin').some((p) => p.endsWith('scripts/typedoc-plugin.mjs'))).toBe(true);
    expect(validation.invalidLink).toBe(true);
    expect(app.options.getValue('treatWarningsAsErrors')).toBe(true);
    expect(problems).toEqual([]);
    expect(app.logger.errorCount + app.logger.warningCount).toBe(0);
  });

  it('documents the two packages, by their names, and nothing else', () => {
    const modules = project.getChildrenByKind(ReflectionKind.Module);
    expect(modules.map((m) => m.name).sort()).toEqual(['@maxgrid/engine', '@maxgrid/scenes']);
    for (const m of modules) expect(m.hasComment(), m.name).toBe(true);
  });

  it("writes World's page with the main methods on it", () => {
    const world = project.getChildByName(['@maxgrid/engine', 'World']);
    expect(world?.kind).toBe(ReflectionKind.Class);
    const html = readFileSync(join(out, 'classes', '_maxgrid_engine.World.html'), 'utf8');
    for (const name of WORLD_MAIN_MEMBERS) {
      expect(world!.getChildByName(name), name).toBeDefined();
      expect(html, name).toContain(`id="${name.toLowerCase()}"`);
    }
  });

  it('has a comment on every exported declaration, class member and function', () => {
    const missing = project
      .getReflectionsByKind(DECLARED)
      .filter((r) => !inTypeLiteral(r))
      // An interface's fields are many and mostly self-naming (x, vx, mass); a class's are the API.
      .filter((r) => !r.kindOf(ReflectionKind.Property) || r.parent?.kindOf(ReflectionKind.Class))
      .filter((r) => !documented(r))
      .map((r) => r.getFriendlyFullName());
    expect(missing).toEqual([]);
  });
});
