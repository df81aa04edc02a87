import type { Host } from '../experiments/common.js';
import { cBaseline } from './native.js';

/** Node's capabilities for experiments: the C baseline, and a headless Chromium on demand. */
export function nodeHost(): Host {
  return {
    cBaseline,
    async browser() {
      // Loaded only when an experiment asks: vite and playwright-core are heavy.
      const { chromiumHost } = await import('./chromium.js');
      return chromiumHost();
    },
    async sandbox() {
      const { sandboxHost } = await import('./chromium.js');
      return sandboxHost();
    },
    async busyProcesses(count: number) {
      const { startBusyProcesses } = await import('./busy.js');
      return startBusyProcesses(count);
    },
    async hostScaling() {
      const { measureHostScaling } = await import('./host-scaling.js');
      return measureHostScaling();
    },
  };
}
