// The geometry of each primitive, from its parameters as the problem format writes them
// (Shape::to_json): one builder per `type`, which the list of primitives in
// grader/shapes/primitives.h must match (tests/scene_view_in_browser.py draws every problem of
// the bank and fails on an object no builder knows). An object with a `matrix` (its transform,
// object to world) is placed by it.
import * as THREE from 'three';

const vec = (a) => new THREE.Vector3(a[0], a[1], a[2]);
const Y = new THREE.Vector3(0, 1, 0);
const Z = new THREE.Vector3(0, 0, 1);

// A mesh of `geometry` whose local +y (or `from`) is turned to the unit `axis` and whose local
// origin is put at `at`.
function placed(geometry, material, at, axis, from = Y) {
  const mesh = new THREE.Mesh(geometry, material);
  mesh.quaternion.setFromUnitVectors(from, axis);
  mesh.position.copy(at);
  return mesh;
}

// The point of the line through `point` along the unit `axis` nearest to `c`.
function nearestOnLine(point, axis, c) {
  return point.clone().addScaledVector(axis, c.clone().sub(point).dot(axis));
}

// Vertices of a flat polygon (any simple one, convex or not) as triangles.
function flatGeometry(points) {
  const normal = new THREE.Vector3();
  for (let i = 0; i < points.length; ++i) {  // Newell's method
    const a = points[i];
    const b = points[(i + 1) % points.length];
    normal.x += (a.y - b.y) * (a.z + b.z);
    normal.y += (a.z - b.z) * (a.x + b.x);
    normal.z += (a.x - b.x) * (a.y + b.y);
  }
  normal.normalize();
  const u = new THREE.Vector3().subVectors(points[1], points[0]).normalize();
  const v = new THREE.Vector3().crossVectors(normal, u);
  const flat = points.map((p) => new THREE.Vector2(p.clone().sub(points[0]).dot(u),
    p.clone().sub(points[0]).dot(v)));
  const triangles = THREE.ShapeUtils.triangulateShape(flat, []);
  const positions = [];
  for (const t of triangles) for (const k of t) positions.push(points[k].x, points[k].y, points[k].z);
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
  geometry.computeVertexNormals();
  return geometry;
}

// The builders: (parameters, frame {centre, radius}, material) → an Object3D in object space.
const BUILDERS = {
  sphere: (s, frame, m) => {
    const mesh = new THREE.Mesh(new THREE.SphereGeometry(s.radius, 48, 24), m);
    mesh.position.copy(vec(s.center));
    return mesh;
  },
  // An infinite plane as a square around the point of the plane nearest the scene's centre.
  plane: (s, frame, m) => {
    const n = vec(s.normal);
    const length = n.length();
    n.normalize();
    const point = s.point ? vec(s.point) : n.clone().multiplyScalar(-s.d / length);
    const at = frame.centre.clone().sub(n.clone().multiplyScalar(frame.centre.clone().sub(point).dot(n)));
    const side = frame.radius * 2.4;
    return placed(new THREE.PlaneGeometry(side, side), m, at, n, Z);
  },
  triangle: (s, frame, m) => new THREE.Mesh(flatGeometry(s.vertices.map(vec)), m),
  polygon: (s, frame, m) => new THREE.Mesh(flatGeometry(s.vertices.map(vec)), m),
  disk: (s, frame, m) =>
    placed(new THREE.CircleGeometry(s.radius, 64), m, vec(s.center), vec(s.normal).normalize(), Z),
  box: (s, frame, m) => {
    const lo = vec(s.min);
    const hi = vec(s.max);
    const mesh = new THREE.Mesh(new THREE.BoxGeometry(hi.x - lo.x, hi.y - lo.y, hi.z - lo.z), m);
    mesh.position.copy(lo.add(hi).multiplyScalar(0.5));
    return mesh;
  },
  // Finite with a height (open, or closed by caps); infinite without one: drawn as long as the
  // scene is wide, centred where the axis passes nearest the scene's centre.
  cylinder: (s, frame, m) => {
    const axis = vec(s.axis || [0, 0, 1]).normalize();
    const base = vec(s.base);
    const infinite = s.height === undefined;
    const height = infinite ? frame.radius * 2.6 : s.height;
    const middle = infinite ? nearestOnLine(base, axis, frame.centre)
      : base.clone().addScaledVector(axis, height / 2);
    const geometry = new THREE.CylinderGeometry(s.radius, s.radius, height, 48, 1,
      infinite || !s.capped);
    return placed(geometry, m, middle, axis);
  },
  cone: (s, frame, m) => {
    const axis = vec(s.axis || [0, 0, 1]).normalize();
    const middle = vec(s.base).addScaledVector(axis, s.height / 2);
    const geometry = new THREE.CylinderGeometry(0, s.radius, s.height, 48, 1, !s.capped);
    return placed(geometry, m, middle, axis);
  },
  capsule: (s, frame, m) => {
    const a = vec(s.a);
    const b = vec(s.b);
    const axis = b.clone().sub(a);
    const length = axis.length();
    const geometry = new THREE.CapsuleGeometry(s.radius, length, 12, 48);
    return placed(geometry, m, a.add(b).multiplyScalar(0.5), axis.normalize());
  },
};

// The object of the scene data {label, shape, matrix?} in the world, or null for a type no
// builder knows.
export function buildObject(object, frame, colour) {
  const build = BUILDERS[object.shape.type];
  if (!build) return null;
  const material = new THREE.MeshPhongMaterial({
    color: colour, side: THREE.DoubleSide, transparent: true, opacity: 0.62, shininess: 40,
    depthWrite: false,
  });
  // A transformed object is built in object space, where the scene's frame is taken too.
  let local = frame;
  let matrix = null;
  if (object.matrix) {
    const r = object.matrix;
    matrix = new THREE.Matrix4().set(r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8], r[9],
      r[10], r[11], 0, 0, 0, 1);
    const inverse = matrix.clone().invert();
    const scale = matrix.getMaxScaleOnAxis();
    local = { centre: frame.centre.clone().applyMatrix4(inverse), radius: frame.radius / scale };
  }
  const mesh = build(object.shape, local, material);
  mesh.name = object.label || object.shape.type;
  if (!matrix) return mesh;
  const group = new THREE.Group();
  group.matrixAutoUpdate = false;
  group.matrix.copy(matrix);
  group.add(mesh);
  return group;
}
