// When a Max Grid bins in bands (GridKernel.binBanded, parallel/banded-bin.ts), in which bands,
// and with how much scratch: the decisions of a banded bin, apart from the memory it works in.

/**
 * When a grid bins in two levels (assembly `binBanded`, or parallel/banded-bin.ts on a parallel
 * step's threads): from `minBodies` bodies on, when the last bin found more than a quarter of them
 * scattered (see assembly `jumps`), in bands of about `bodiesPerBand` bodies at uniform density.
 * Tests lower both to reach the banded bin with few bodies; not part of the public API.
 * Measured on `uniform`, the bin alone on prepared inputs and whole steps on one thread and two
 * (docs/engine.md, Numbers): on bodies created row by row the banded bin is the slower at every
 * size; on shuffled bodies it gains nothing up to about 100,000 and wins from 250,000 on, by less
 * inside a stepping world, which evicts the grid between bins. So it pays only where bodies are
 * scattered, and only above L2-sized grids.
 */
export const bandedBin = { minBodies: 1 << 17, bodiesPerBand: 4096 };

/** Plain bins before a grid whose bodies crowded into a few bands tries banding again (about a second at 60 Hz). */
const BANDED_PAUSE = 60;

/**
 * One grid's banding decisions. The bin itself says how scattered its bodies were (jumps) and how
 * full its fullest band was; this turns that into the next bin's kind and room.
 */
export class BandedPolicy {
  /** The bands `choose` picked: cells per band (log 2), and how many. */
  shift = 0;
  bands = 0;
  /** Banded bins refused for a band too full for the scratch: for tests. */
  refusals = 0;
  /** The scratch (in bodies) the fullest refused band asked for. */
  private scratchWanted = 0;
  /** Bins left before banding is tried again, after a band held more than an eighth of the bodies. */
  private pause = 0;

  /**
   * Whether the next bin of n bodies should be banded: at least bandedBin.minBodies of them, and
   * more than a quarter of them jumps in the last bin (assembly `jumps`).
   */
  wants(n: number, jumps: number): boolean {
    if (n < bandedBin.minBodies) return false;
    if (this.pause > 0) {
      this.pause--;
      return false;
    }
    return 4 * jumps > n;
  }

  /**
   * Chooses bands for n bodies over `cells` cells, about bandedBin.bodiesPerBand bodies each at
   * uniform density, and returns the scratch the bin needs, in bodies.
   */
  choose(n: number, cells: number): number {
    // The least shift whose bands of 2^shift cells hold about bodiesPerBand bodies: counted, not
    // Math.log2, whose rounding each JavaScript engine chooses (see the determinism test).
    let shift = 0;
    while (2 ** shift * n < cells * bandedBin.bodiesPerBand) shift++;
    this.shift = shift;
    this.bands = ((cells - 1) >> this.shift) + 1;
    // Twice a band's share at uniform density, before any bin has said what the fullest band needs.
    return Math.max(this.scratchWanted, Math.ceil((2 * n) / this.bands));
  }

  /**
   * Notes a band of `most` bodies too full for the scratch, and returns false: the next `choose`
   * asks for room for it, unless it holds more than an eighth of all bodies (they crowd into a few
   * bands, where banding does not pay); then the next BANDED_PAUSE bins are plain.
   */
  refuse(most: number, n: number): false {
    this.refusals++;
    if (8 * most <= n) this.scratchWanted = most;
    else this.pause = BANDED_PAUSE;
    return false;
  }
}

/**
 * A parallel banded bin's plan, between its counts and its partition: in `rows`, each share's row
 * of band counts (bands + 1 int32 per share) becomes its cursors (band b's start, plus the bodies
 * of that band in earlier shares), and the band starts are laid out in the row after the last
 * share's. Returns how many bodies the fullest band holds.
 */
export function planBandStarts(rows: Int32Array, shares: number, bands: number, n: number): number {
  const starts = shares * (bands + 1);
  let at = 0;
  let most = 0;
  for (let b = 0; b < bands; b++) {
    rows[starts + b] = at;
    const first = at;
    for (let share = 0; share < shares; share++) {
      const count = rows[share * (bands + 1) + b];
      rows[share * (bands + 1) + b] = at;
      at += count;
    }
    most = Math.max(most, at - first);
  }
  rows[starts + bands] = n;
  return most;
}
