// The 3D view of a problem's scene: the objects with their real geometry, the given ray, the
// lights and the camera, and on a worked solution the hits, their normals and the rays of a ray
// tree. raygrade writes the scene as JSON into the page (grader/reports/scene_view.h); this
// script builds a three.js scene from it and lets the reader orbit around it with the mouse,
// touch or the keyboard. scripts/build-viewer.sh bundles it into one classic script that defines
// window.raygradeSceneView.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

import { buildObject } from './objects.js';

// Colours: objects take the palette in turn; the rest have one colour each.
const PALETTE = [0x4e79a7, 0x59a14f, 0xb07aa1, 0x76b7b2, 0xedc948, 0x9c755f, 0xff9da7, 0xbab0ac];
const COLOURS = {
  background: 0xf6f6f2,
  ray: 0x111111,
  origin: 0x111111,
  point: 0x6a3d9a,
  light: 0xe6a800,
  camera: 0x555555,
  pixel: 0xff7f0e,
  hit: 0xd62728,
  normal: 0x1f77b4,
  primary: 0x111111,
  reflection: 0x1f77b4,
  refraction: 0x2ca02c,
  shadow: 0x888888,
  answer: 0xd62728,
};

const vec = (a) => new THREE.Vector3(a[0], a[1], a[2]);

// A line through the points, in the given colour.
function polyline(points, colour, closed = false) {
  const geometry = new THREE.BufferGeometry().setFromPoints(points);
  const Kind = closed ? THREE.LineLoop : THREE.Line;
  return new Kind(geometry, new THREE.LineBasicMaterial({ color: colour }));
}

// A ball that marks a point, sized to the scene.
function marker(at, colour, size) {
  const mesh = new THREE.Mesh(new THREE.SphereGeometry(size, 16, 8),
    new THREE.MeshBasicMaterial({ color: colour }));
  mesh.position.copy(at);
  return mesh;
}

// An arrow from `from` along the unit `direction`, `length` long: a shaft and a cone.
function arrow(from, direction, length, colour, size) {
  const group = new THREE.Group();
  const head = Math.min(length * 0.3, size * 4);
  const end = from.clone().addScaledVector(direction, length - head);
  // The shaft is a thin tube rather than a line, which WebGL draws one pixel wide.
  const shaft = new THREE.Mesh(new THREE.CylinderGeometry(size * 0.4, size * 0.4, length - head, 8),
    new THREE.MeshBasicMaterial({ color: colour }));
  shaft.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), direction);
  shaft.position.copy(from).addScaledVector(direction, (length - head) / 2);
  group.add(shaft);
  const cone = new THREE.Mesh(new THREE.ConeGeometry(size * 1.4, head, 16),
    new THREE.MeshBasicMaterial({ color: colour }));
  cone.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), direction);
  cone.position.copy(end).addScaledVector(direction, head / 2);
  group.add(cone);
  return group;
}

function addCamera(scene, camera, size) {
  const eye = vec(camera.eye);
  const corners = camera.corners.map(vec);
  scene.add(marker(eye, COLOURS.camera, size * 1.2));
  scene.add(polyline(corners, COLOURS.camera, true));
  for (const c of corners) {
    if (camera.orthographic) {
      scene.add(polyline([c, c.clone().addScaledVector(vec(camera.look), size * 8)],
        COLOURS.camera));
    } else {
      scene.add(polyline([eye, c], COLOURS.camera));
    }
  }
  if (camera.pixel) {
    const p = camera.pixel.map(vec);
    const geometry = new THREE.BufferGeometry().setFromPoints([p[0], p[1], p[2], p[0], p[2], p[3]]);
    scene.add(new THREE.Mesh(geometry, new THREE.MeshBasicMaterial(
      { color: COLOURS.pixel, side: THREE.DoubleSide })));
  }
}

function addAnswers(scene, answers, frame, size) {
  for (const s of answers.segments || []) {
    const from = vec(s.from);
    const to = vec(s.to);
    const line = polyline([from, to], COLOURS[s.role] ?? COLOURS.answer);
    if (s.role === 'shadow') {
      line.material = new THREE.LineDashedMaterial(
        { color: COLOURS.shadow, dashSize: size * 2, gapSize: size * 1.5 });
      line.computeLineDistances();
    }
    scene.add(line);
  }
  for (const h of answers.hits || []) {
    const at = vec(h.point);
    scene.add(marker(at, COLOURS.hit, size * 1.1));
    if (h.normal) {
      scene.add(arrow(at, vec(h.normal).normalize(), frame.radius * 0.25, COLOURS.normal, size * 0.6));
    }
  }
}

// The initial eye: oblique to the ray (or the camera's look, or the first given arrow) so that
// neither is seen end-on.
function initialEye(data, centre, distance) {
  // not a part: an arrow's role in the view (the given ray)
  const first = (data.arrows || []).find((a) => a.role === 'ray');
  const along = data.ray ? vec(data.ray.direction) : data.camera ? vec(data.camera.look)
    : first ? vec(first.to).sub(vec(first.from)) : null;
  let offset = new THREE.Vector3(0.62, 0.48, 1).normalize();
  if (along && along.lengthSq() > 0 && Math.abs(offset.dot(along.clone().normalize())) > 0.8) {
    offset = new THREE.Vector3(1, 0.48, -0.62).normalize();
  }
  return centre.clone().addScaledVector(offset, distance);
}

// Builds the view of `data` into `container` (its text, if any, is the fallback and goes).
// Returns {renderer, camera, controls, render, reset}.
function mount(container, data) {
  const frame = { centre: vec(data.frame.center), radius: Math.max(data.frame.radius, 1e-6) };
  const size = frame.radius * 0.012;
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(COLOURS.background);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x666666, 2.2));
  const sun = new THREE.DirectionalLight(0xffffff, 1.4);
  sun.position.set(0.4, 1, 0.7);
  scene.add(sun);
  const axes = new THREE.AxesHelper(frame.radius * 0.25);
  scene.add(axes);

  let unknown = 0;
  data.objects.forEach((o, i) => {
    const object = buildObject(o, frame, PALETTE[i % PALETTE.length]);
    if (object) scene.add(object); else ++unknown;
  });
  if (data.ray) {
    const origin = vec(data.ray.origin);
    scene.add(marker(origin, COLOURS.origin, size));
    scene.add(arrow(origin, vec(data.ray.direction).normalize(), frame.radius * 0.5, COLOURS.ray, size));
  }
  for (const p of data.points || []) {
    scene.add(marker(vec(p.at), p.label === 'eye' ? COLOURS.camera : COLOURS.point, size * 1.2));
  }
  // Given directions drawn where they act: a surface's normal, a ray arriving at a point.
  for (const a of data.arrows || []) {
    const from = vec(a.from);
    const along = vec(a.to).sub(from);
    const length = along.length();
    if (length > 0) {
      scene.add(arrow(from, along.normalize(), length, COLOURS[a.role] ?? COLOURS.ray, size * 0.8));
    }
  }
  for (const l of data.lights || []) {
    if (l.position) {
      const bulb = new THREE.Mesh(new THREE.OctahedronGeometry(size * 2.5),
        new THREE.MeshBasicMaterial({ color: COLOURS.light }));
      bulb.position.copy(vec(l.position));
      scene.add(bulb);
    } else if (l.direction) {
      const d = vec(l.direction).normalize();
      const from = frame.centre.clone().addScaledVector(d, -frame.radius * 0.9);
      scene.add(arrow(from, d, frame.radius * 0.3, COLOURS.light, size));
    }
  }
  if (data.camera) addCamera(scene, data.camera, size);
  if (data.answers) addAnswers(scene, data.answers, frame, size);

  const canvas = document.createElement('canvas');
  canvas.tabIndex = 0;
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label', container.dataset.label || '3D view of the scene');
  if (container.dataset.describedby) canvas.setAttribute('aria-describedby', container.dataset.describedby);
  canvas.className = 'scene-view-canvas';
  const width = container.clientWidth || 640;
  const height = Math.round(width * 0.6);
  const renderer = new THREE.WebGLRenderer(
    { canvas, antialias: true, preserveDrawingBuffer: true, powerPreference: 'low-power' });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setSize(width, height);
  container.textContent = '';
  container.appendChild(canvas);

  const camera = new THREE.PerspectiveCamera(40, width / height, frame.radius * 0.01, frame.radius * 100);
  const controls = new OrbitControls(camera, canvas);
  controls.listenToKeyEvents(canvas);
  const render = () => renderer.render(scene, camera);
  const reset = () => {
    camera.up.set(0, 1, 0);
    camera.position.copy(initialEye(data, frame.centre, frame.radius * 2.4));
    controls.target.copy(frame.centre);
    controls.update();
    render();
  };
  controls.addEventListener('change', render);
  // Keys beside OrbitControls' own (arrows pan; with Shift, Ctrl or Cmd they rotate): + and −
  // zoom, 0 or Home puts the view back.
  canvas.addEventListener('keydown', (event) => {
    if (event.key === '+' || event.key === '=') zoom(1 / 1.15);
    else if (event.key === '-' || event.key === '_') zoom(1.15);
    else if (event.key === '0' || event.key === 'Home') reset();
    else return;
    event.preventDefault();
  });
  function zoom(factor) {
    camera.position.sub(controls.target).multiplyScalar(factor).add(controls.target);
    controls.update();
    render();
  }
  reset();
  container.dataset.ready = unknown ? 'unknown-object' : 'drawn';
  return { renderer, camera, controls, render, reset, scene };
}

// Draws one view from its element: an element with class scene-view whose data-scene attribute
// names the id of the <script type="application/json"> element holding its scene.
function mountElement(container) {
  if (container.dataset.ready) return null;
  try {
    const data = JSON.parse(document.getElementById(container.dataset.scene).textContent);
    return mount(container, data);
  } catch (error) {
    container.dataset.ready = 'failed';
    container.textContent = 'The 3D view could not be drawn here (' + error.message +
      '); the sketch above shows the scene.';
    return null;
  }
}

// Draws every view of the page now.
function mountAll(root = document) {
  return [...root.querySelectorAll('.scene-view[data-scene]')].map(mountElement).filter(Boolean);
}

// Draws each view when it comes near the screen, once the page has loaded and the browser is
// idle: a view costs a WebGL context and its shaders, which must not hold up the page (a
// practice page's grader) nor be spent on views nobody scrolls to.
function mountWhenSeen(root = document) {
  const views = root.querySelectorAll('.scene-view[data-scene]');
  if (!('IntersectionObserver' in window)) {
    views.forEach(mountElement);
    return;
  }
  const observer = new IntersectionObserver((entries) => {
    for (const entry of entries) {
      if (!entry.isIntersecting) continue;
      observer.unobserve(entry.target);
      setTimeout(() => mountElement(entry.target), 0);
    }
  }, { rootMargin: '200px' });
  views.forEach((view) => observer.observe(view));
}

window.raygradeSceneView = { mount, mountAll, version: THREE.REVISION };
const later = window.requestIdleCallback || ((f) => setTimeout(f, 50));
if (document.readyState === 'complete') {
  later(() => mountWhenSeen());
} else {
  window.addEventListener('load', () => later(() => mountWhenSeen()));
}
