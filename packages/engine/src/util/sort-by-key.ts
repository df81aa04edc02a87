/**
 * Stable ascending sort of `values` by `keys` (both of length >= n), in place, using caller-owned
 * scratch so that a step never allocates. Bottom-up merge sort over insertion-sorted runs:
 * O(n log n) whatever the input, unlike Array.prototype.sort whose comparator calls and internal
 * copies would allocate on every step.
 */
const RUN = 24;

export function sortByKey(
  keys: Float64Array,
  values: Int32Array,
  n: number,
  scratchKeys: Float64Array,
  scratchValues: Int32Array,
): void {
  for (let start = 0; start < n; start += RUN) {
    const end = Math.min(start + RUN, n);
    for (let i = start + 1; i < end; i++) {
      const key = keys[i];
      const value = values[i];
      let j = i - 1;
      while (j >= start && keys[j] > key) {
        keys[j + 1] = keys[j];
        values[j + 1] = values[j];
        j--;
      }
      keys[j + 1] = key;
      values[j + 1] = value;
    }
  }
  let srcK = keys;
  let srcV = values;
  let dstK = scratchKeys;
  let dstV = scratchValues;
  for (let width = RUN; width < n; width *= 2) {
    for (let left = 0; left < n; left += 2 * width) {
      const mid = Math.min(left + width, n);
      const right = Math.min(left + 2 * width, n);
      let i = left;
      let j = mid;
      let k = left;
      while (i < mid && j < right) {
        // `<=` takes from the left run on ties, which keeps the sort stable.
        if (srcK[i] <= srcK[j]) {
          dstK[k] = srcK[i];
          dstV[k++] = srcV[i++];
        } else {
          dstK[k] = srcK[j];
          dstV[k++] = srcV[j++];
        }
      }
      while (i < mid) {
        dstK[k] = srcK[i];
        dstV[k++] = srcV[i++];
      }
      while (j < right) {
        dstK[k] = srcK[j];
        dstV[k++] = srcV[j++];
      }
    }
    const tk = srcK;
    srcK = dstK;
    dstK = tk;
    const tv = srcV;
    srcV = dstV;
    dstV = tv;
  }
  if (srcK !== keys) {
    keys.set(srcK.subarray(0, n));
    values.set(srcV.subarray(0, n));
  }
}

/** Below this many values sortFew sorts by insertion; from it on, by heap sort. */
const FEW = 32;

/**
 * values[0, n) ascending, in place, allocating nothing: by insertion for the few values a search
 * usually finds, and by heap sort, O(n log n) whatever their order, for many (a box over a whole
 * terrain of segments listed in the tree's order: insertion took 600 ms for 32,000 of them).
 */
export function sortFew(values: Int32Array, n: number): void {
  if (n >= FEW) {
    heapSort(values, n);
    return;
  }
  for (let i = 1; i < n; i++) {
    const v = values[i];
    let j = i - 1;
    while (j >= 0 && values[j] > v) {
      values[j + 1] = values[j];
      j--;
    }
    values[j + 1] = v;
  }
}

function heapSort(values: Int32Array, n: number): void {
  for (let start = (n >> 1) - 1; start >= 0; start--) siftDown(values, start, n);
  for (let end = n - 1; end > 0; end--) {
    const top = values[0];
    values[0] = values[end];
    values[end] = top;
    siftDown(values, 0, end);
  }
}

/** Moves values[root] down the max-heap values[0, end) to its place. */
function siftDown(values: Int32Array, root: number, end: number): void {
  const v = values[root];
  let parent = root;
  for (;;) {
    let child = 2 * parent + 1;
    if (child >= end) break;
    if (child + 1 < end && values[child + 1] > values[child]) child++;
    if (values[child] <= v) break;
    values[parent] = values[child];
    parent = child;
  }
  values[parent] = v;
}
