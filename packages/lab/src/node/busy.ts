import { spawn } from 'node:child_process';

// Spins, and exits once its parent is gone (it is then re-parented), so a crashed lab leaves no load behind.
const BUSY = "const parent = process.ppid; process.stdout.write('up\\n'); for (;;) { for (let i = 0; i < 1e7; i++); if (process.ppid !== parent) process.exit(); }";

/**
 * `count` Node processes spinning in a loop, one core's worth of load each, for measuring the
 * engine on an oversubscribed machine. Resolves once they run; the function it resolves to kills
 * them (and they exit by themselves once this process is gone).
 */
export async function startBusyProcesses(count: number): Promise<() => void> {
  const children = Array.from({ length: count }, () =>
    spawn(process.execPath, ['-e', BUSY], { stdio: ['ignore', 'pipe', 'ignore'] }),
  );
  await Promise.all(children.map((child) => new Promise<void>((resolve, reject) => {
    child.stdout!.once('data', () => resolve());
    child.once('error', reject);
  })));
  return () => {
    for (const child of children) child.kill('SIGKILL');
  };
}
