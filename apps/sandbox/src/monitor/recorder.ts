import { Ring } from './ring.js';

export const COLUMNS = ['time', 'step_ms', 'kinetic', 'potential', 'total', 'candidate_pairs', 'contacts'] as const;
export type Column = (typeof COLUMNS)[number];

/**
 * The per-step series behind the graphs and the `Download data` button (report 5.13). About 18
 * minutes of 60 Hz steps; after that the oldest steps are dropped, so memory stays bounded.
 */
export class Recorder {
  static readonly CAPACITY = 65_536;
  readonly series: Record<Column, Ring>;

  constructor(capacity = Recorder.CAPACITY) {
    const series = {} as Record<Column, Ring>;
    for (const c of COLUMNS) series[c] = new Ring(capacity);
    this.series = series;
  }

  get length(): number {
    return this.series.time.length;
  }

  record(time: number, stepMs: number, kinetic: number, potential: number, candidates: number, contacts: number): void {
    const s = this.series;
    s.time.push(time);
    s.step_ms.push(stepMs);
    s.kinetic.push(kinetic);
    s.potential.push(potential);
    s.total.push(kinetic + potential);
    s.candidate_pairs.push(candidates);
    s.contacts.push(contacts);
  }

  /** Forgets the newest `n` steps: the scrubber went back over them. */
  dropLast(n: number): void {
    for (const c of COLUMNS) this.series[c].dropLast(n);
  }

  clear(): void {
    for (const c of COLUMNS) this.series[c].clear();
  }
}
