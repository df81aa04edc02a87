/*
 * maxgrid's hardware baseline (issue 5, target 2): the same step as @maxgrid/engine with the
 * maxgrid broad-phase, written as plain single-threaded C, so that the lab can say how far the
 * TypeScript engine is from what the machine can do with the same algorithm:
 *   semi-implicit Euler -> box walls -> counting-sort Max Grid with cell-ordered copies, forward
 *   half-neighbourhood scan with padded box test -> circle narrow-phase -> contacts in canonical
 *   (lo, hi) order by two counting passes -> sequential impulses + mass-weighted separation ->
 *   clamp into the box.
 * It reproduces the engine's arithmetic operation for operation, so the final state hash must match
 * the engine's bit for bit: the lab checks that before it trusts any timing.
 *
 * Input (binary, little-endian): int32 n, f64 width, f64 height, f64 gravityY, f64 restitution,
 * then n records of f64 x, y, vx, vy, radius. Arguments: <scene.bin> <steps> <dt> <warmup>.
 * Output (one JSON line): per-step times in ms after warm-up, and the state hash.
 * Build: gcc -O3 -march=native -ffp-contract=off -o maxgrid maxgrid.c -lm
 * (-ffp-contract=off: GCC would otherwise fuse a*b+c into FMA instructions, which round once
 * where JavaScript rounds twice, and the hashes would differ.)
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define RADIUS_PAD (1.0 / 1048576.0) /* 2^-20, as fat-bounds.ts */
#define COORD_PAD (1.0 / 1099511627776.0) /* 2^-40 */
#define MAX_BOUNCES 16

static int n;
static double width, height, gravity_y, wall_e;
static double *x, *y, *vx, *vy, *rad, *mass, *inv_mass, *rest;
static int32_t *cell_start, *live_cell, *sorted_slot;
static double *sx, *sy, *sr;
static int32_t *clo, *chi, *tlo, *thi, *counts;
static int ncontacts, contact_cap, cell_cap;
static double max_radius;

static void *xmalloc(size_t bytes) {
  void *p = malloc(bytes);
  if (!p) { fprintf(stderr, "out of memory\n"); exit(2); }
  return p;
}

static void integrate(double dt) {
  double dvy = gravity_y * dt;
  for (int i = 0; i < n; i++) {
    vx[i] += 0.0 * dt;
    vy[i] += dvy;
    x[i] += vx[i] * dt;
    y[i] += vy[i] * dt;
  }
}

static void fold(double *pp, double *vp, double lo, double hi, double e) {
  double p = *pp, v = *vp;
  for (int b = 0; b < MAX_BOUNCES; b++) {
    if (p < lo) p = lo + (lo - p) * e;
    else if (p > hi) p = hi - (p - hi) * e;
    else break;
    v = -v * e;
  }
  if (!(p >= lo && p <= hi)) {
    double span = hi - lo;
    if (!isfinite(p) || span <= 0) p = lo + span / 2;
    else {
      double u = fmod(p - lo, 2 * span);
      if (u < 0) u += 2 * span;
      if (u > span) { u = 2 * span - u; v = -v; }
      p = fmin(hi, fmax(lo, lo + u));
    }
  }
  *pp = p; *vp = v;
}

static void walls(void) {
  for (int i = 0; i < n; i++) {
    double r = rad[i];
    if (x[i] < r || x[i] > width - r) fold(&x[i], &vx[i], r, width - r, rest[i] > wall_e ? rest[i] : wall_e);
    if (y[i] < r || y[i] > height - r) fold(&y[i], &vy[i], r, height - r, rest[i] > wall_e ? rest[i] : wall_e);
  }
}

static void push_contact(int a, int b) {
  if (ncontacts == contact_cap) {
    contact_cap *= 2;
    clo = realloc(clo, contact_cap * sizeof *clo); chi = realloc(chi, contact_cap * sizeof *chi);
    tlo = realloc(tlo, contact_cap * sizeof *tlo); thi = realloc(thi, contact_cap * sizeof *thi);
  }
  if (a < b) { clo[ncontacts] = a; chi[ncontacts] = b; } else { clo[ncontacts] = b; chi[ncontacts] = a; }
  ncontacts++;
}

/* Narrow-phase inline on the candidate: same test and same operand order as circle-circle.ts. */
static inline void candidate(int i, int j) {
  double dx = x[j] - x[i], dy = y[j] - y[i], reach = rad[i] + rad[j];
  if (dx * dx + dy * dy < reach * reach) push_contact(i, j);
}

static void broadphase(void) {
  /* Like the engine in a boxed world: after the walls every centre is inside the box. */
  double minx = 0, miny = 0, maxx = width, maxy = height;
  double reach = fmax(fmax(fabs(minx), fabs(maxx)), fmax(fabs(miny), fabs(maxy)));
  double cs = 2 * max_radius * (1 + RADIUS_PAD) + reach * COORD_PAD;
  double inv = 1 / cs;
  int columns = (int)floor((maxx - minx) * inv) + 1, rows = (int)floor((maxy - miny) * inv) + 1;
  while ((double)columns * rows > 4.0 * n + 64) {
    cs *= 1.5; inv = 1 / cs;
    columns = (int)floor((maxx - minx) * inv) + 1; rows = (int)floor((maxy - miny) * inv) + 1;
  }
  int cells = columns * rows;
  if (cells + 2 > cell_cap) { cell_cap = 2 * (cells + 2); cell_start = realloc(cell_start, cell_cap * sizeof *cell_start); }
  memset(cell_start, 0, (cells + 2) * sizeof *cell_start);
  for (int i = 0; i < n; i++) {
    int c = (int)((y[i] - miny) * inv) * columns + (int)((x[i] - minx) * inv);
    live_cell[i] = c;
    cell_start[c]++;
  }
  for (int c = 1; c < cells; c++) cell_start[c] += cell_start[c - 1];
  for (int k = n - 1; k >= 0; k--) {
    int c = live_cell[k], at = --cell_start[c];
    sorted_slot[at] = k;
    sx[at] = x[k]; sy[at] = y[k]; sr[at] = rad[k] * (1 + RADIUS_PAD);
  }
  cell_start[cells] = n; cell_start[cells + 1] = n;
  double pad = reach * COORD_PAD;
  /* Cell by cell, as cell-grid.ts scanSelf: neighbour ranges once per cell. */
  for (int row = 0; row < rows; row++) {
    int row_start = row * columns, has_below = row + 1 < rows;
    for (int column = 0; column < columns; column++) {
      int c = row_start + column, first = cell_start[c], last = cell_start[c + 1];
      if (first == last) continue;
      int same_end = cell_start[column + 1 < columns ? c + 2 : c + 1], from = 0, to = 0;
      if (has_below) {
        int below = c + columns;
        from = cell_start[column > 0 ? below - 1 : below];
        to = cell_start[column + 1 < columns ? below + 2 : below + 1];
      }
      for (int k = first; k < last; k++) {
        double ax = sx[k], ay = sy[k], ar = sr[k] + pad;
        int a = sorted_slot[k];
        for (int m = k + 1; m < same_end; m++) {
          double rr = ar + sr[m], dx = sx[m] - ax, dy = sy[m] - ay;
          if (dx * dx + dy * dy <= rr * rr) candidate(a, sorted_slot[m]);
        }
        for (int m = from; m < to; m++) {
          double rr = ar + sr[m], dx = sx[m] - ax, dy = sy[m] - ay;
          if (dx * dx + dy * dy <= rr * rr) candidate(a, sorted_slot[m]);
        }
      }
    }
  }
}

static void counting_pass(const int32_t *key, const int32_t *slo, const int32_t *shi, int32_t *dlo, int32_t *dhi) {
  memset(counts, 0, (n + 1) * sizeof *counts);
  for (int k = 0; k < ncontacts; k++) counts[key[k] + 1]++;
  for (int s = 0; s < n; s++) counts[s + 1] += counts[s];
  for (int k = 0; k < ncontacts; k++) { int at = counts[key[k]]++; dlo[at] = slo[k]; dhi[at] = shi[k]; }
}

static void radix_pass(const int32_t *key, int shift, const int32_t *slo, const int32_t *shi, int32_t *dlo, int32_t *dhi) {
  int32_t buckets[256] = {0};
  for (int k = 0; k < ncontacts; k++) buckets[(key[k] >> shift) & 255]++;
  for (int b = 0, sum = 0; b < 256; b++) { int c = buckets[b]; buckets[b] = sum; sum += c; }
  for (int k = 0; k < ncontacts; k++) { int at = buckets[(key[k] >> shift) & 255]++; dlo[at] = slo[k]; dhi[at] = shi[k]; }
}

/* Same choice as contact-buffer.ts: radix over the contacts when few, counting by slot when many. */
static void sort_contacts(void) {
  if (ncontacts < 2) return;
  if ((long)ncontacts * 8 < n) {
    int bytes = 1;
    while (bytes < 4 && n > (1L << (8 * bytes))) bytes++;
    int32_t *slo = clo, *shi = chi, *dlo = tlo, *dhi = thi;
    for (int pass = 0; pass < 2 * bytes; pass++) {
      int key_is_hi = pass < bytes, shift = 8 * (key_is_hi ? pass : pass - bytes);
      radix_pass(key_is_hi ? shi : slo, shift, slo, shi, dlo, dhi);
      int32_t *t = slo; slo = dlo; dlo = t; t = shi; shi = dhi; dhi = t;
    }
    return;
  }
  counting_pass(chi, clo, chi, tlo, thi);
  counting_pass(tlo, tlo, thi, clo, chi);
}

static void solve(void) {
  sort_contacts();
  for (int k = 0; k < ncontacts; k++) {
    int i = clo[k], j = chi[k];
    double dx = x[j] - x[i], dy = y[j] - y[i], reach = rad[i] + rad[j], d2 = dx * dx + dy * dy;
    if (d2 >= reach * reach) continue;
    double wi = inv_mass[i], wj = inv_mass[j], w = wi + wj;
    if (w == 0) continue;
    double nx = 1, ny = 0, dist = sqrt(d2);
    if (dist > 0) { nx = dx / dist; ny = dy / dist; }
    double vn = (vx[j] - vx[i]) * nx + (vy[j] - vy[i]) * ny;
    if (vn < 0) {
      double e = rest[i] > rest[j] ? rest[i] : rest[j];
      double impulse = (-(1 + e) * vn) / w, pi = impulse * wi, pj = impulse * wj;
      vx[i] -= pi * nx; vy[i] -= pi * ny; vx[j] += pj * nx; vy[j] += pj * ny;
    }
    double overlap = reach - dist, si = (overlap * wi) / w, sj = (overlap * wj) / w;
    x[i] -= si * nx; y[i] -= si * ny; x[j] += sj * nx; y[j] += sj * ny;
  }
}

static void clamp_body(int i) {
  double r = rad[i];
  if (x[i] < r) x[i] = r; else if (x[i] > width - r) x[i] = width - r;
  if (y[i] < r) y[i] = r; else if (y[i] > height - r) y[i] = height - r;
}

/* As box-walls.ts clampIntoBox: only bodies the solver moved can have left the box. */
static void clamp_box(void) {
  for (int k = 0; k < ncontacts; k++) { clamp_body(clo[k]); clamp_body(chi[k]); }
}

/* Same digest as analytics.ts stateHash (all bodies dynamic, slots 0..n-1). */
static void state_hash(char out[17]) {
  uint32_t h1 = 0x811c9dc5u, h2 = 0x01000193u ^ 0x5bd1e995u;
#define MIX(v) do { uint32_t w_ = (uint32_t)(v); h1 = (h1 ^ w_) * 0x01000193u; h2 = ((h2 ^ w_) * 0x5bd1e995u) ^ (h2 >> 13); } while (0)
  double *cols[4] = {x, y, vx, vy};
  for (int i = 0; i < n; i++) {
    MIX(i); MIX(3);
    for (int c = 0; c < 4; c++) { uint32_t w[2]; memcpy(w, &cols[c][i], 8); MIX(w[0]); MIX(w[1]); }
  }
  snprintf(out, 17, "%08x%08x", h1, h2);
}

static double now_ms(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

int main(int argc, char **argv) {
  if (argc != 5) { fprintf(stderr, "usage: %s scene.bin steps dt warmup\n", argv[0]); return 1; }
  FILE *f = fopen(argv[1], "rb");
  if (!f) { perror(argv[1]); return 1; }
  int steps = atoi(argv[2]), warmup = atoi(argv[4]);
  double dt = atof(argv[3]);
  if (fread(&n, 4, 1, f) != 1 || fread(&width, 8, 1, f) != 1 || fread(&height, 8, 1, f) != 1 ||
      fread(&gravity_y, 8, 1, f) != 1 || fread(&wall_e, 8, 1, f) != 1) { fprintf(stderr, "bad header\n"); return 1; }
  double **cols[] = {&x, &y, &vx, &vy, &rad, &mass, &inv_mass, &rest, &sx, &sy, &sr};
  for (size_t c = 0; c < sizeof cols / sizeof *cols; c++) *cols[c] = xmalloc((n + 1) * sizeof(double));
  int32_t **icols[] = {&live_cell, &sorted_slot, &counts};
  for (size_t c = 0; c < sizeof icols / sizeof *icols; c++) *icols[c] = xmalloc((n + 2) * sizeof(int32_t));
  contact_cap = 1024;
  clo = xmalloc(contact_cap * 4); chi = xmalloc(contact_cap * 4); tlo = xmalloc(contact_cap * 4); thi = xmalloc(contact_cap * 4);
  for (int i = 0; i < n; i++) {
    double rec[5];
    if (fread(rec, 8, 5, f) != 5) { fprintf(stderr, "short file\n"); return 1; }
    x[i] = rec[0]; y[i] = rec[1]; vx[i] = rec[2]; vy[i] = rec[3]; rad[i] = rec[4];
    mass[i] = 1 * M_PI * rad[i] * rad[i];
    inv_mass[i] = 1 / mass[i];
    rest[i] = wall_e;
    if (rad[i] > max_radius) max_radius = rad[i];
  }
  fclose(f);
  printf("{\"n\":%d,\"stepMs\":[", n);
  for (int s = 0; s < warmup + steps; s++) {
    double t0 = now_ms();
    integrate(dt);
    walls();
    ncontacts = 0;
    broadphase();
    solve();
    clamp_box();
    double t1 = now_ms();
    if (s >= warmup) printf("%s%.6f", s > warmup ? "," : "", t1 - t0);
  }
  char hash[17];
  state_hash(hash);
  printf("],\"hash\":\"%s\"}\n", hash);
  return 0;
}
