import type { Vec3 } from './types';

/** A new vector (x, y, z). */
export function vec3(x: number, y: number, z: number): Vec3 {
  return { x, y, z };
}

/** Dot product. */
export function dot(u: Vec3, v: Vec3): number {
  return u.x * v.x + u.y * v.y + u.z * v.z;
}

/** Cross product u x v. */
export function cross(u: Vec3, v: Vec3): Vec3 {
  return { x: u.y * v.z - u.z * v.y, y: u.z * v.x - u.x * v.z, z: u.x * v.y - u.y * v.x };
}

/** u - v. */
export function sub(u: Vec3, v: Vec3): Vec3 {
  return { x: u.x - v.x, y: u.y - v.y, z: u.z - v.z };
}

/** u + v. */
export function add(u: Vec3, v: Vec3): Vec3 {
  return { x: u.x + v.x, y: u.y + v.y, z: u.z + v.z };
}

/** k u. */
export function scale(u: Vec3, k: number): Vec3 {
  return { x: u.x * k, y: u.y * k, z: u.z * k };
}

/** Euclidean norm, without overflow or underflow of the squares. */
export function norm(u: Vec3): number {
  return Math.hypot(u.x, u.y, u.z);
}
