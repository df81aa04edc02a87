/**
 * A body's state through the soft step's sub-steps, BODY doubles per moving body (state 0 is the
 * fixed dummy that static and sleeping bodies share): velocity, and its motion since the step
 * began, as a delta position and a delta rotation (cos, sin). Contacts and joints read and write
 * these rows; positions are applied to the bodies once, after the sub-steps.
 */
export const VX = 0;
export const VY = 1;
export const W = 2;
export const DPX = 3;
export const DPY = 4;
export const DQC = 5;
export const DQS = 6;
/** 1 for a dynamic body; 0 for a kinematic one and the dummy, whose velocity no impulse changes. */
export const DYNAMIC = 7;
export const BODY = 8;

/**
 * Box2D's b2MakeSoft: the bias rate, mass scale and impulse scale of a spring of `hertz` with
 * damping ratio `zeta` over a sub-step h, into out[at..at + 2].
 */
export function makeSoft(hertz: number, zeta: number, h: number, out: Float64Array, at = 0): void {
  const omega = 2 * Math.PI * hertz;
  const a1 = 2 * zeta + h * omega;
  const a2 = h * omega * a1;
  const a3 = 1 / (1 + a2);
  out[at] = omega / a1;
  out[at + 1] = a2 * a3;
  out[at + 2] = a3;
}

/**
 * How many of a body's radii of gyration, sqrt(I / m), from its centre make a lever arm far: the
 * contacts' arms are held within it (soft-step.ts, armScale) and joints past it hold their bodies
 * within the speed limits (joint-solver.ts, farArms). Rounding in an impulse's spin change then
 * feeds the next constraint at most 1e-16 FAR_ARM^2 = 1e-4 of it.
 */
export const FAR_ARM = 1e6;

/**
 * Caps the state row at s within the speed limits, keeping the velocity's direction: an impulse
 * a long lever arm multiplied enters the next pass within them. Scaled in two steps, so that a
 * speed whose square overflows still comes back finite.
 */
export function holdState(states: Float64Array, s: number, maxSpeed: number, maxAngular: number): void {
  const vx = states[s + VX];
  const vy = states[s + VY];
  const w = states[s + W];
  if (vx * vx + vy * vy > maxSpeed * maxSpeed) {
    const largest = Math.max(Math.abs(vx), Math.abs(vy));
    const ux = vx / largest;
    const uy = vy / largest;
    const ratio = maxSpeed / Math.sqrt(ux * ux + uy * uy);
    states[s + VX] = ux * ratio;
    states[s + VY] = uy * ratio;
  }
  if (w * w > maxAngular * maxAngular) states[s + W] = w > 0 ? maxAngular : -maxAngular;
}
