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

/** values[0, n) ascending, in place: an insertion sort, for the short lists a search finds (nearly in order, allocating nothing). */
export function sortFew(values: Int32Array, n: number): void {
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
