import { existsSync, readFileSync, readdirSync } from 'node:fs';
import { dirname, join, normalize, relative } from 'node:path';
import { ESLint } from 'eslint';
import { describe, expect, it } from 'vitest';

// docs/ARCHITECTURE.md's table says which folders each folder may import. This reads the table and checks every
// relative import in src against it, so the document cannot drift from the code (ESLint fences the same layers by
// pattern; this checks the document's own words).

const ROOT = join(import.meta.dirname, '..');

interface Row {
  folder: string;
  allowed: string[];
}

/** The table's rows: the folder (first cell) and the backticked src paths of the "may import" cell (last cell). */
function tableRows(markdown: string): Row[] {
  const rows: Row[] = [];
  for (const line of markdown.split('\n')) {
    const cells = line.split('|').map((c) => c.trim());
    if (cells.length < 5 || !/^`src\//.test(cells[1])) continue;
    const folder = cells[1].replace(/`/g, '').replace(/\/$/, '');
    const allowed = [...cells[cells.length - 2].matchAll(/`(src\/[^`]*)`/g)].map((m) => m[1].replace(/\/$/, ''));
    rows.push({ folder, allowed });
  }
  return rows;
}

function sourceFiles(dir: string): string[] {
  return readdirSync(join(ROOT, dir), { withFileTypes: true, recursive: true })
    .filter((e) => e.isFile() && /\.tsx?$/.test(e.name))
    .map((e) => relative(ROOT, join(e.parentPath, e.name)));
}

const inside = (path: string, folder: string) => path === folder || path.startsWith(`${folder}/`);

/** The most specific row whose folder holds path. */
function rowOf(rows: readonly Row[], path: string): Row | undefined {
  return rows.filter((r) => inside(path, r.folder)).sort((a, b) => b.folder.length - a.folder.length)[0];
}

/** Relative import specifiers of a source file, resolved to repository paths. */
function relativeImports(file: string): string[] {
  const text = readFileSync(join(ROOT, file), 'utf8');
  return [...text.matchAll(/(?:from|import)\s*\(?\s*['"](\.{1,2}\/[^'"]*)['"]/g)].map((m) =>
    normalize(join(dirname(file), m[1].split('?')[0])),
  );
}

const rows = tableRows(readFileSync(join(ROOT, 'docs/ARCHITECTURE.md'), 'utf8'));

describe('docs/ARCHITECTURE.md', () => {
  it('has a row for every folder of src, and every row names a folder that exists', () => {
    expect(rows.length).toBeGreaterThan(15);
    for (const r of rows) expect(existsSync(join(ROOT, r.folder)), r.folder).toBe(true);
    for (const file of sourceFiles('src')) expect(rowOf(rows, file), file).toBeDefined();
  });

  it('says the truth about imports: each relative import stays in its folder or lands in one the table allows', () => {
    const broken: string[] = [];
    for (const file of sourceFiles('src')) {
      const row = rowOf(rows, file)!;
      for (const target of relativeImports(file)) {
        if (inside(target, row.folder) || row.allowed.some((a) => inside(target, a))) continue;
        broken.push(`${file} imports ${target} (${row.folder} may import ${row.allowed.join(', ') || 'nothing'})`);
      }
    }
    expect(broken).toEqual([]);
  });

  it('reads the table as written (the checker itself)', () => {
    const md = '| `src/a/` | x | `src/b`, `src/c/` |\n| `src/a/d/` | y | nothing |\n| not | a | row |';
    expect(tableRows(md)).toEqual([
      { folder: 'src/a', allowed: ['src/b', 'src/c'] },
      { folder: 'src/a/d', allowed: [] },
    ]);
    expect(rowOf(tableRows(md), 'src/a/d/e.ts')?.folder).toBe('src/a/d');
  });
});

describe('eslint.config.js', () => {
  const features = readdirSync(join(ROOT, 'src/features'), { withFileTypes: true })
    .filter((e) => e.isDirectory())
    .map((e) => e.name);

  it('fences every folder under src/features: an import of another feature is an error', async () => {
    const eslint = new ESLint({ cwd: ROOT });
    for (const feature of features) {
      const other = features.find((f) => f !== feature)!;
      const text = `import { x } from '../${other}/x';\nexport const y = x;\n`;
      const [result] = await eslint.lintText(text, { filePath: join(ROOT, `src/features/${feature}/probe.ts`) });
      const rules = result.messages.map((m) => m.ruleId);
      expect(rules, `features/${feature} importing features/${other}`).toContain('no-restricted-imports');
    }
  }, 30_000);

  it('lets a feature import shared kits and the numerics', async () => {
    const eslint = new ESLint({ cwd: ROOT });
    const text = "import { x } from '../../shared/x';\nimport { z } from '../../solver/z';\nexport const y = [x, z];\n";
    const [result] = await eslint.lintText(text, { filePath: join(ROOT, 'src/features/report/probe.ts') });
    expect(result.messages.map((m) => m.ruleId)).not.toContain('no-restricted-imports');
  });
});
