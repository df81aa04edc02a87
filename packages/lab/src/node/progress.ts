import { SingleBar, Presets } from 'cli-progress';
import type { Progress } from '../experiments/common.js';

/**
 * A progress bar on stderr (stdout stays clean for piping), or nothing when stderr is not a
 * terminal, so logs and CI output carry no control characters.
 */
export function progressBar(label: string, stream: NodeJS.WriteStream = process.stderr): { progress: Progress; stop(): void } {
  if (!stream.isTTY) return { progress: () => {}, stop: () => {} };
  const bar = new SingleBar(
    { stream, format: `${label} [{bar}] {percentage}% {value}/{total} {task}`, hideCursor: true, clearOnComplete: false },
    Presets.shades_classic,
  );
  let started = false;
  return {
    progress(done, total, task) {
      if (!started) {
        bar.start(total, done, { task });
        started = true;
      } else bar.update(done, { task });
    },
    stop() {
      if (started) bar.stop();
    },
  };
}
