// The break scene: a strike runs hedge's fracture in wasm on the shown mesh, and each shard (surface
// fracture) or piece (solid fracture) becomes a rigid body of cannon-es that falls under gravity and
// settles on a ground plane.
//
// Bodies. Each shard is a closed solid (the strike gives it a thickness), and each piece of a solid
// fracture is one by construction, so the fracture returns its mass, centre of mass and inertia
// tensor. A body sits at the shard's centre of mass, turned to its
// principal axes: there the tensor is diagonal, which is what cannon-es stores, so mass and inertia
// are the fracture's exact values (set after addShape, which would put in an approximation from the
// bounding box). The collider is a ConvexPolyhedron of the shard's convex hull, in the same frame.
// Shards collide with the ground, not with each other: dozens of convex pairs touching from the
// first step would cost more than the rest of the frame and add nothing to a demonstration.
import * as THREE from 'three';
import * as CANNON from 'cannon-es';
import { toBufferGeometry } from 'hedge/three';

export const STEP = 1 / 60;

//! A flat plate of n x n squares, each cut into two triangles (2 n^2 faces), `size` wide, lying in
//! the y = height plane and centred on the y axis. {positions, indices} for hedge.fromBuffers.
export function plateArrays(n, size, height) {
  const positions = new Float32Array((n + 1) * (n + 1) * 3);
  for (let j = 0, k = 0; j <= n; ++j)
    for (let i = 0; i <= n; ++i, k += 3)
      positions.set([(i / n - 0.5) * size, height, (j / n - 0.5) * size], k);
  const indices = new Uint32Array(n * n * 6);
  const at = (i, j) => j * (n + 1) + i;
  for (let j = 0, k = 0; j < n; ++j)
    for (let i = 0; i < n; ++i, k += 6) {
      // Counter-clockwise seen from above (+y).
      indices.set(
        [at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i + 1, j)],
        k,
      );
    }
  return { positions, indices };
}

//! Median of a list of numbers (NaN when empty).
export function median(values) {
  if (values.length === 0) return NaN;
  const s = [...values].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
}

export class BreakWorld {
  //! scene: the three.js scene the shards and the ground go into.
  constructor(scene) {
    this.scene = scene;
    this.group = new THREE.Group();
    this.scene.add(this.group);
    this.world = new CANNON.World({ gravity: new CANNON.Vec3(0, -9.82, 0), allowSleep: true });
    this.world.defaultContactMaterial.friction = 0.5;
    this.world.defaultContactMaterial.restitution = 0;
    this.world.solver.iterations = 20;
    this.groundBody = null;
    this.groundY = 0;
    this.shards = []; // {body, mesh}
    this.steps = 0;
    this.material = new THREE.MeshStandardMaterial({
      color: 0x7fb2d9,
      roughness: 0.35,
      metalness: 0.05,
      flatShading: true,
    });
    // A solid fracture's pieces: the object's colour outside, the inner colour on their caps.
    this.pieceMaterial = new THREE.MeshStandardMaterial({ color: 0xb9c4d0, roughness: 0.7 });
    this.innerMaterial = new THREE.MeshStandardMaterial({ color: 0xc9774b, roughness: 0.9 });
    this.groundMesh = null;
  }

  //! Puts the ground plane at height y (a static body, and a grid drawn there), `extent` wide.
  setGround(y, extent) {
    this.clear();
    this.groundY = y;
    this.groundBody = new CANNON.Body({
      mass: 0,
      type: CANNON.Body.STATIC,
      shape: new CANNON.Plane(),
    });
    // The plane's normal is its local +z: turn it to +y.
    this.groundBody.quaternion.setFromEuler(-Math.PI / 2, 0, 0);
    this.groundBody.position.set(0, y, 0);
    this.world.addBody(this.groundBody);
    const grid = new THREE.GridHelper(extent, 20, 0x9aa3ab, 0xc9ced3);
    grid.position.y = y;
    const floor = new THREE.Mesh(
      new THREE.PlaneGeometry(extent, extent),
      new THREE.MeshStandardMaterial({ color: 0xe3e1dc, roughness: 0.95 }),
    );
    floor.rotation.x = -Math.PI / 2;
    floor.position.y = y - 1e-3 * extent;
    this.groundMesh = new THREE.Group();
    this.groundMesh.add(floor, grid);
    this.group.add(this.groundMesh);
  }

  //! Removes every shard and the ground.
  clear() {
    for (const { body, mesh } of this.shards) {
      this.world.removeBody(body);
      this.group.remove(mesh);
      mesh.geometry.dispose();
    }
    this.shards = [];
    if (this.groundBody) this.world.removeBody(this.groundBody);
    this.groundBody = null;
    if (this.groundMesh) {
      this.group.remove(this.groundMesh);
      this.groundMesh.traverse((o) => {
        if (o.geometry) o.geometry.dispose();
        if (o.material) o.material.dispose();
      });
    }
    this.groundMesh = null;
    this.steps = 0;
  }

  //! Adds one shard of a fracture result as a body and a mesh. `away`: the unit direction it is
  //! pushed in, `speed` the velocity the push gives it (m/s). The shard's hedge mesh is read here;
  //! the caller disposes it afterwards.
  addShard(shard, away, speed) {
    if (!shard.closed || !(shard.mass > 0))
      throw new Error('a shard without a thickness has no mass to simulate');
    this.addBody(shard, away, speed, (toLocal) => {
      const { positions, indices } = shard.mesh.toArrays({ triangulate: true });
      const local = new Float32Array(positions.length);
      for (let i = 0; i < positions.length; i += 3)
        local.set(toLocal(positions[i], positions[i + 1], positions[i + 2]), i);
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(local, 3));
      geometry.setIndex(new THREE.BufferAttribute(indices, 1));
      geometry.computeVertexNormals();
      return new THREE.Mesh(geometry, this.material);
    });
  }

  //! Adds one piece of a solid fracture (Mesh.fractureSolid) as a body and a mesh, its caps (the
  //! faces of submesh `innerSubmesh`) drawn in the inner colour; `away` and `speed` as for
  //! addShard. The piece's hedge mesh is read here; the caller disposes it afterwards.
  addPiece(piece, away, speed, innerSubmesh) {
    if (!(piece.mass > 0)) throw new Error(`a piece of mass ${piece.mass} cannot be simulated`);
    this.addBody(piece, away, speed, (toLocal, com, rotation) => {
      // One group per submesh (toBufferGeometry), moved into the body's frame. The corner normals
      // are made anew, hard along the caps' rims (the caps' own corners carry their plane's).
      piece.mesh.computeCornerNormals(40);
      const geometry = toBufferGeometry(piece.mesh, { texcoords: false, colors: false });
      geometry.applyMatrix4(
        rotation
          .clone()
          .transpose()
          .multiply(new THREE.Matrix4().makeTranslation(-com.x, -com.y, -com.z)),
      );
      const materials = Array.from({ length: innerSubmesh + 1 }, (_, i) =>
        i === innerSubmesh ? this.innerMaterial : this.pieceMaterial,
      );
      return new THREE.Mesh(geometry, materials);
    });
  }

  //! The body of a closed part (a shard or a piece: mass, centreOfMass, principalAxes,
  //! principalMoments, hull) and its drawn mesh, made by draw(toLocal, com, rotation) in the frame
  //! of its principal axes.
  addBody(shard, away, speed, draw) {
    const com = new THREE.Vector3(...shard.centreOfMass);
    const [a0, a1, a2] = shard.principalAxes.map((a) => new THREE.Vector3(...a));
    const rotation = new THREE.Matrix4().makeBasis(a0, a1, a2);
    const toLocal = (x, y, z) => {
      const d = new THREE.Vector3(x - com.x, y - com.y, z - com.z);
      return [d.dot(a0), d.dot(a1), d.dot(a2)];
    };

    // The collider: the hull in the principal frame.
    const hp = shard.hull.positions;
    const vertices = [];
    for (let i = 0; i < hp.length; i += 3)
      vertices.push(new CANNON.Vec3(...toLocal(hp[i], hp[i + 1], hp[i + 2])));
    const faces = [];
    const hi = shard.hull.indices;
    for (let i = 0; i < hi.length; i += 3) faces.push([hi[i], hi[i + 1], hi[i + 2]]);
    const shape = new CANNON.ConvexPolyhedron({ vertices, faces });

    const body = new CANNON.Body({
      mass: shard.mass,
      shape,
      collisionFilterGroup: 2,
      collisionFilterMask: 1,
    });
    // Some damping, as air and the contact would give: a curved shard rocks on its hull's
    // vertices, and without it the solver's small errors keep it rocking.
    body.linearDamping = 0.1;
    body.angularDamping = 0.4;
    body.allowSleep = true;
    body.sleepSpeedLimit = 0.05;
    body.sleepTimeLimit = 0.5;
    // The fracture's mass properties, exact in this frame (addShape put in a box's).
    const [i0, i1, i2] = shard.principalMoments;
    body.mass = shard.mass;
    body.invMass = 1 / shard.mass;
    body.inertia.set(i0, i1, i2);
    body.invInertia.set(1 / i0, 1 / i1, 1 / i2);
    body.position.set(com.x, com.y, com.z);
    const q = new THREE.Quaternion().setFromRotationMatrix(rotation);
    body.quaternion.set(q.x, q.y, q.z, q.w);
    body.updateInertiaWorld(true);
    body.applyImpulse(
      new CANNON.Vec3(
        away[0] * speed * shard.mass,
        away[1] * speed * shard.mass,
        away[2] * speed * shard.mass,
      ),
    );
    this.world.addBody(body);

    // What is drawn: the part's own faces, in the same frame.
    const mesh = draw(toLocal, com, rotation);
    mesh.position.copy(com);
    mesh.quaternion.copy(q);
    this.group.add(mesh);
    this.shards.push({ body, mesh });
  }

  //! Advances the simulation by `steps` fixed steps and moves the meshes to their bodies.
  step(steps) {
    for (let i = 0; i < steps; ++i) this.world.step(STEP);
    this.steps += steps;
    for (const { body, mesh } of this.shards) {
      mesh.position.set(body.position.x, body.position.y, body.position.z);
      mesh.quaternion.set(
        body.quaternion.x,
        body.quaternion.y,
        body.quaternion.z,
        body.quaternion.w,
      );
    }
  }

  //! Shards still moving: awake and faster than 1 cm/s or 0.05 rad/s (a body can hover just above
  //! cannon-es's sleep limit for a long time while it creeps by micrometres).
  get moving() {
    let n = 0;
    for (const { body } of this.shards)
      if (
        body.sleepState !== CANNON.Body.SLEEPING &&
        (body.velocity.length() > 0.01 || body.angularVelocity.length() > 0.05)
      )
        ++n;
    return n;
  }

  //! Where each shard is: {position (centre of mass), lowest (y of its lowest hull vertex), speed,
  //! angularSpeed, asleep}.
  report() {
    const v = new CANNON.Vec3();
    return this.shards.map(({ body }) => {
      const shape = body.shapes[0];
      let lowest = Infinity;
      for (const p of shape.vertices) {
        body.quaternion.vmult(p, v);
        lowest = Math.min(lowest, v.y + body.position.y);
      }
      return {
        position: [body.position.x, body.position.y, body.position.z],
        lowest,
        speed: body.velocity.length(),
        angularSpeed: body.angularVelocity.length(),
        asleep: body.sleepState === CANNON.Body.SLEEPING,
      };
    });
  }

  dispose() {
    this.clear();
    this.material.dispose();
    this.pieceMaterial.dispose();
    this.innerMaterial.dispose();
    this.scene.remove(this.group);
  }
}
