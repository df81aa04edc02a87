/** A fixed-capacity series of numbers: pushing past capacity forgets the oldest. No allocation. */
export class Ring {
  readonly data: Float64Array;
  private head = 0;
  private size = 0;

  constructor(readonly capacity: number) {
    this.data = new Float64Array(capacity);
  }

  get length(): number {
    return this.size;
  }

  push(value: number): void {
    this.data[this.head] = value;
    this.head = (this.head + 1) % this.capacity;
    if (this.size < this.capacity) this.size++;
  }

  /** The i-th value, oldest first. */
  at(i: number): number {
    return this.data[(this.head - this.size + i + this.capacity) % this.capacity];
  }

  last(): number {
    return this.size === 0 ? NaN : this.at(this.size - 1);
  }

  /** Forgets the newest `n` values (all of them for n beyond the length). */
  dropLast(n: number): void {
    const k = Math.min(this.size, Math.max(0, Math.floor(n)));
    this.head = (this.head - k + this.capacity) % this.capacity;
    this.size -= k;
  }

  clear(): void {
    this.head = 0;
    this.size = 0;
  }
}
