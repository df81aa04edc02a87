/**
 * The slice of p2-es the adapter uses, declared by hand. p2-es's own declarations define ambient
 * modules ("world/World", "objects/Body", ...) with the same names as cannon-es's, so any
 * TypeScript program that sees both (the sandbox, which hosts the lab page and the 3D page)
 * fails to type-check. Loading p2-es through this untyped .js shim keeps its declarations out.
 */
export type Vec2 = Float32Array | number[];

export interface P2Body {
  position: Vec2;
  velocity: Vec2;
  angle: number;
  angularVelocity: number;
  shapes: object[];
  addShape(shape: object, offset?: [number, number], angle?: number): void;
  updateMassProperties(): void;
  adjustCenterOfMass(): void;
  updateAABB(): void;
}

export interface P2RevoluteConstraint {
  setLimits(lower: number, upper: number): void;
  motorEnabled: boolean;
  motorSpeed: number;
  motorMaxForce: number;
}

export interface P2World {
  sleepMode: number;
  defaultContactMaterial: { restitution: number; friction: number };
  addBody(body: P2Body): void;
  addConstraint(constraint: object): void;
  step(dt: number): void;
  clear(): void;
}

export interface P2Api {
  World: {
    new (options: { gravity: [number, number]; solver: object; islandSplit: boolean }): P2World;
    NO_SLEEPING: number;
  };
  Body: {
    new (options: {
      mass: number;
      type?: number;
      position: [number, number];
      angle?: number;
      velocity?: [number, number];
      angularVelocity?: number;
      fixedRotation?: boolean;
      damping?: number;
      angularDamping?: number;
      allowSleep?: boolean;
    }): P2Body;
    STATIC: number;
    DYNAMIC: number;
    KINEMATIC: number;
  };
  Circle: new (options: { radius: number }) => object;
  Box: new (options: { width: number; height: number }) => object;
  Capsule: new (options: { length: number; radius: number }) => object;
  Convex: new (options: { vertices: number[][] }) => object;
  Line: new (options: { length: number }) => object;
  GSSolver: new (options: { iterations: number }) => object;
  RevoluteConstraint: new (bodyA: P2Body, bodyB: P2Body, options: { localPivotA: [number, number]; localPivotB: [number, number]; collideConnected: boolean }) => P2RevoluteConstraint;
  DistanceConstraint: new (bodyA: P2Body, bodyB: P2Body, options: { localAnchorA: [number, number]; localAnchorB: [number, number]; distance: number; collideConnected: boolean }) => object;
}

export function loadP2(): Promise<P2Api>;
