import { cpus, platform, release, totalmem } from 'node:os';
import type { Environment } from '../experiments/common.js';

/** What the numbers were measured on, as written into every output. */
export function nodeEnvironment(): Environment {
  const list = cpus();
  return {
    runtime: `Node.js ${process.version}`,
    v8: process.versions.v8,
    cores: list.length,
    cpu: list[0]?.model.trim() ?? 'unknown',
    platform: `${platform()} ${release()}`,
    memoryGiB: Math.round((totalmem() / 2 ** 30) * 10) / 10,
  };
}
