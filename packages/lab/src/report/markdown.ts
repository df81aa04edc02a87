import type { AnyExperiment } from '../experiments/registry.js';
import { markdownTable } from './tables.js';

/** The machine line every markdown output carries (docs/results.md and each experiment's .md). */
export function machineLine(e: Record<string, string | number>): string {
  return `Machine: ${e.cpu}, ${e.cores} cores, ${e.memoryGiB} GiB, ${e.platform}; ${e.runtime} (V8 ${e.v8})`;
}

/**
 * An experiment's section body: its headline (which carries its own paragraph breaks), its charts
 * as images at `images` (paths relative to the markdown file), then its tables.
 */
export function sectionMarkdown(experiment: AnyExperiment, result: unknown, images: { id: string; path: string }[]): string[] {
  return [
    ...experiment.headline(result),
    '',
    ...images.flatMap((c) => [`![${c.id}](${c.path})`, '']),
    ...experiment.tables(result).flatMap((t) => [markdownTable(t), '']),
  ];
}
