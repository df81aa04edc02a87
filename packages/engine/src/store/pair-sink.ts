/** What consumes candidate pairs in chunks: the narrow-phase. */
export interface PairConsumer {
  consume(a: Int32Array, b: Int32Array, count: number): void;
  /** Contacts (lo < hi) a broad-phase found touching itself, which need no test (see contactsDirect): pairs as ContactSink.pushPairs takes them. */
  accept(pairs: Int32Array, from: number, to: number): void;
}

/**
 * The broad-phase's output. Candidates collect in a fixed chunk that is handed to the consumer
 * whenever it fills, and once more at the end. A fixed chunk keeps memory bounded whatever the
 * candidate count (the naive broad-phase emits n(n-1)/2 pairs: 5e9 at 100k bodies), and still
 * lets the narrow-phase run as a separate, separately timed loop over plain arrays.
 */
export class PairSink {
  static readonly CHUNK = 8192;

  readonly a = new Int32Array(PairSink.CHUNK);
  readonly b = new Int32Array(PairSink.CHUNK);
  /** Pairs waiting in the chunk. */
  pending = 0;
  /** Every pair pushed since `begin`: the broad-phase's output count. */
  total = 0;
  /** Time spent inside the consumer, so the caller can split broad-phase from narrow-phase time. */
  consumerMs = 0;
  /**
   * Set by the step when every pair of its bodies collides (BodyStore.everyPairCollides), so the
   * narrow-phase would only test each pair for touching: a broad-phase that can test as it finds
   * may then hand over contacts (pushContacts) instead of candidates.
   */
  contactsDirect = false;

  constructor(
    private readonly consumer: PairConsumer,
    private readonly clock: () => number,
  ) {}

  begin(): void {
    this.pending = 0;
    this.total = 0;
    this.consumerMs = 0;
  }

  push(i: number, j: number): void {
    const k = this.pending;
    this.a[k] = i;
    this.b[k] = j;
    if (++this.pending === PairSink.CHUNK) this.flush();
  }

  /**
   * Touching pairs, as (lo, hi) in pairs[from..to), that the broad-phase found and tested while
   * `contactsDirect`, out of `candidates` pairs whose padded circles overlapped.
   */
  pushContacts(pairs: Int32Array, from: number, to: number, candidates: number): void {
    this.total += candidates;
    this.consumer.accept(pairs, from, to);
  }

  memoryBytes(): number {
    return this.a.byteLength + this.b.byteLength;
  }

  /** Hands over whatever is pending; broad-phases need not call it, the step does. */
  flush(): void {
    if (this.pending === 0) return;
    const started = this.clock();
    this.total += this.pending;
    this.consumer.consume(this.a, this.b, this.pending);
    this.pending = 0;
    this.consumerMs += this.clock() - started;
  }
}
