// The three.js scene: the mesh (GpuMesh), the camera and its orbit controls, and the overlays that
// show the hovered element, its one-ring and its half-edges.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { GpuMesh, UploadMeter } from './gpu_mesh.js';

const COLORS = {
  surface: 0xb9c4d0,
  inner: 0xc9774b, // the inside of a broken solid: its cap faces
  wire: 0x34404c,
  face: 0xffa31a,
  edge: 0xe0206a,
  vertex: 0x1a8cff,
  ring: 0x18a558,
  halfedge: 0xe0206a,
  next: 0x1a8cff,
  prev: 0x8a4fd0,
  twin: 0xe69500,
};
export { COLORS };

export class Viewer {
  constructor(canvas) {
    this.canvas = canvas;
    // preserveDrawingBuffer keeps the last frame readable for screenshots.
    this.renderer = new THREE.WebGLRenderer({
      canvas,
      antialias: true,
      preserveDrawingBuffer: true,
    });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
    this.meter = new UploadMeter(this.renderer.getContext());
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0xf4f4f2);
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1000);
    this.camera.position.set(0, 0, 3);
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.addEventListener('change', () => this.requestRender());

    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x667788, 1.6));
    const sun = new THREE.DirectionalLight(0xffffff, 1.6);
    sun.position.set(2, 3, 4);
    this.camera.add(sun);
    this.scene.add(this.camera);

    const material = new THREE.MeshStandardMaterial({
      color: COLORS.surface,
      roughness: 0.7,
      metalness: 0.0,
      side: THREE.DoubleSide,
      flatShading: false,
      polygonOffset: true,
      polygonOffsetFactor: 1,
      polygonOffsetUnits: 1,
    });
    const lineMaterial = new THREE.LineBasicMaterial({
      color: COLORS.wire,
      transparent: true,
      opacity: 0.45,
    });
    this.material = material;
    // The caps of a solid fracture (one submesh, see setInnerSubmesh): the surface's look, another colour.
    this.innerMaterial = material.clone();
    this.innerMaterial.color.set(COLORS.inner);
    this.mesh = new GpuMesh(material, lineMaterial);
    this.scene.add(this.mesh.group);

    this.overlay = new THREE.Group();
    this.scene.add(this.overlay);

    this.raycaster = new THREE.Raycaster();
    this.pending = false;
    this.onResize = () => this.resize();
    window.addEventListener('resize', this.onResize);
    this.resize();
  }

  resize() {
    const { clientWidth: w, clientHeight: h } = this.canvas;
    if (w === 0 || h === 0) return;
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.requestRender();
  }

  requestRender() {
    if (this.pending) return;
    this.pending = true;
    requestAnimationFrame(() => {
      this.pending = false;
      this.render();
    });
  }

  render() {
    this.renderer.render(this.scene, this.camera);
  }

  //! Draws the surface see-through (a glass plate, with what is under it in view), or not.
  setSeeThrough(on) {
    for (const m of [this.material, this.innerMaterial]) {
      m.transparent = on;
      m.opacity = on ? 0.45 : 1;
      m.depthWrite = !on;
      m.needsUpdate = true;
    }
    this.requestRender();
  }

  //! Draws submesh `k` (a group of the geometry) in the inner colour and every other submesh in
  //! the surface's; null: one material for all.
  setInnerSubmesh(k) {
    this.mesh.surface.material =
      k === null
        ? this.material
        : Array.from({ length: k + 1 }, (_, i) => (i === k ? this.innerMaterial : this.material));
    this.requestRender();
  }

  setWireframe(on) {
    this.mesh.wireframe.visible = on;
    this.requestRender();
  }

  //! Frames the camera on a bounding box {min: [x,y,z], max: [x,y,z]}, looking from `from` (a
  //! direction from the box's centre).
  frame(box, from = [-0.7, 0.35, -1]) {
    const min = new THREE.Vector3(...box.min);
    const max = new THREE.Vector3(...box.max);
    const center = min.clone().add(max).multiplyScalar(0.5);
    const radius = Math.max(max.distanceTo(min) * 0.5, 1e-6);
    this.controls.target.copy(center);
    const fov = THREE.MathUtils.degToRad(this.camera.fov);
    const distance = (radius / Math.sin(fov / 2)) * 1.05;
    this.camera.position
      .copy(center)
      .add(new THREE.Vector3(...from).normalize().multiplyScalar(distance));
    this.camera.near = distance / 100;
    this.camera.far = distance * 100;
    this.camera.updateProjectionMatrix();
    this.controls.update();
    this.requestRender();
  }

  //! The ray under a pointer event, as {origin, direction} arrays in world (= mesh) coordinates.
  rayAt(event) {
    const rect = this.canvas.getBoundingClientRect();
    const ndc = new THREE.Vector2(
      ((event.clientX - rect.left) / rect.width) * 2 - 1,
      -((event.clientY - rect.top) / rect.height) * 2 + 1,
    );
    this.raycaster.setFromCamera(ndc, this.camera);
    const { origin, direction } = this.raycaster.ray;
    return { origin: origin.toArray(), direction: direction.toArray() };
  }

  //! Pixels per world unit at `point` (for choosing between face, edge and vertex under the cursor).
  pixelsPerUnit(point) {
    const p = new THREE.Vector3(...point);
    const distance = p.distanceTo(this.camera.position);
    const h = this.canvas.clientHeight;
    return h / (2 * distance * Math.tan(THREE.MathUtils.degToRad(this.camera.fov) / 2));
  }

  //! Client pixel coordinates of world point p ([x, y, z]).
  project(p) {
    const v = new THREE.Vector3(...p).project(this.camera);
    const rect = this.canvas.getBoundingClientRect();
    return {
      x: rect.left + ((v.x + 1) / 2) * rect.width,
      y: rect.top + ((1 - v.y) / 2) * rect.height,
    };
  }

  clearOverlay() {
    for (const child of [...this.overlay.children]) {
      this.overlay.remove(child);
      child.traverse((o) => {
        if (o.geometry) o.geometry.dispose();
        if (o.material) o.material.dispose();
      });
    }
    this.requestRender();
  }

  // Overlay primitives. Points are [x, y, z] arrays.
  addPolygon(points, color) {
    if (points.length < 3) return;
    const positions = [];
    for (let i = 1; i + 1 < points.length; ++i)
      positions.push(...points[0], ...points[i], ...points[i + 1]);
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
    const material = new THREE.MeshBasicMaterial({
      color,
      transparent: true,
      opacity: 0.55,
      side: THREE.DoubleSide,
      depthTest: true,
      polygonOffset: true,
      polygonOffsetFactor: -2,
      polygonOffsetUnits: -2,
    });
    this.overlay.add(new THREE.Mesh(geometry, material));
  }

  //! A cylinder of `radius` (world units) from a to b.
  addSegment(a, b, color, radius) {
    const start = new THREE.Vector3(...a);
    const end = new THREE.Vector3(...b);
    const length = start.distanceTo(end);
    if (length === 0) return;
    const r = radius;
    const geometry = new THREE.CylinderGeometry(r, r, length, 8, 1, false);
    const mesh = new THREE.Mesh(geometry, new THREE.MeshBasicMaterial({ color }));
    mesh.position.copy(start).add(end).multiplyScalar(0.5);
    mesh.quaternion.setFromUnitVectors(
      new THREE.Vector3(0, 1, 0),
      end.clone().sub(start).normalize(),
    );
    this.overlay.add(mesh);
  }

  //! A ball of `radius` (world units) at p.
  addPoint(p, color, radius) {
    const geometry = new THREE.SphereGeometry(radius, 12, 8);
    const mesh = new THREE.Mesh(geometry, new THREE.MeshBasicMaterial({ color }));
    mesh.position.set(...p);
    this.overlay.add(mesh);
  }

  //! An arrow from a to b, pulled towards `inside` (a face centre) so that the two half-edges of an
  //! edge are told apart.
  addHalfedgeArrow(a, b, inside, color) {
    const A = new THREE.Vector3(...a);
    const B = new THREE.Vector3(...b);
    const C = new THREE.Vector3(...inside);
    const pull = 0.18;
    const from = A.clone().lerp(C, pull).lerp(B, 0.12);
    const to = B.clone().lerp(C, pull).lerp(A, 0.12);
    const dir = to.clone().sub(from);
    const length = dir.length();
    if (length === 0) return;
    const arrow = new THREE.ArrowHelper(
      dir.normalize(),
      from,
      length,
      color,
      length * 0.3,
      length * 0.15,
    );
    // Drawn over everything, after the transparent face highlight (so marked transparent too).
    for (const part of [arrow.line, arrow.cone]) {
      part.material.depthTest = false;
      part.material.transparent = true;
      part.renderOrder = 10;
    }
    this.overlay.add(arrow);
  }

  dispose() {
    window.removeEventListener('resize', this.onResize);
    this.controls.dispose();
    this.mesh.dispose();
    this.renderer.dispose();
  }
}
