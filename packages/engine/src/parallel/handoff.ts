import { ERROR_TEXT, Slot } from './control.js';
import { canBlock, spinWhileEqual } from './host.js';
import { nowMs } from '../util/timer.js';

// The calling thread's side of the control block's protocol (control.ts; worker-entry.ts is the
// workers' side): publish a command, then wait until every worker has counted itself done.

/** Polls of DONE before the caller sleeps in Atomics.wait (where it may), besides the spin budget (host.ts spinBudget). */
const SPIN = 5_000;

/**
 * A worker silent this long is taken as lost (killed, or its thread starved) and the step fails
 * with an error instead of hanging. No share of a step comes near it: a million bodies take ~0.1 s.
 */
const STALL_MS = 20_000;

export function publishCommand(c: Int32Array, command: number): void {
  c[Slot.command] = command;
  Atomics.store(c, Slot.done, 0);
  Atomics.add(c, Slot.seq, 1);
  Atomics.notify(c, Slot.seq);
}

/** Waits until `expected` workers are done with the published command; throws if one failed or stalled. */
export function awaitWorkers(c: Int32Array, expected: number): void {
  let since = 0;
  for (let spin = 0; ; spin++) {
    const done = Atomics.load(c, Slot.done);
    if (done >= expected) break;
    if (spin < SPIN) continue;
    if (spin === SPIN && spinWhileEqual(c, Slot.done, done, c[Slot.spinMicroseconds])) continue;
    if (since === 0) since = nowMs();
    else if (nowMs() - since > STALL_MS) {
      throw new Error(`parallel step stalled: ${done} of ${expected} workers finished command ${c[Slot.command]} within ${STALL_MS} ms`);
    }
    if (canBlock) Atomics.wait(c, Slot.done, done, 20);
  }
  const failed = Atomics.load(c, Slot.failed);
  if (failed !== 0) {
    Atomics.store(c, Slot.failed, 0);
    throw new Error(workerFailure(c, failed));
  }
}

/** What the first of `failed` workers left in the control block (see recordFailure in worker-entry.ts). */
function workerFailure(c: Int32Array, failed: number): string {
  const length = c[Slot.errorLength];
  let text = '';
  for (let i = 0; i < length; i++) text += String.fromCharCode(c[Slot.errorText + i]);
  const cut = length === ERROR_TEXT ? ' [cut]' : '';
  const others = failed > 1 ? ` (and ${failed - 1} more worker${failed > 2 ? 's' : ''})` : '';
  return `worker thread ${c[Slot.failedWorker]} failed during the step${others}: ${text}${cut}`;
}
