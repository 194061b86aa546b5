// Data decoding: the document's arrays travel as little-endian f32/u32 bytes in base64.

/** The bytes of a padded, standard-alphabet base64 string. */
export function decodeBase64(text) {
  const binary = atob(text);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; i++) bytes[i] = binary.charCodeAt(i);
  return bytes;
}

const littleEndian = new Uint8Array(new Uint32Array([1]).buffer)[0] === 1;

function typed(text, Type, get) {
  const bytes = decodeBase64(text ?? '');
  const n = Math.floor(bytes.length / 4);
  if (littleEndian) return new Type(bytes.buffer, 0, n);
  const view = new DataView(bytes.buffer);
  const out = new Type(n);
  for (let i = 0; i < n; i++) out[i] = get(view, i * 4);
  return out;
}

/** A base64 string of little-endian f32 as a Float32Array. */
export const f32 = (text) => typed(text, Float32Array, (v, o) => v.getFloat32(o, true));
/** A base64 string of little-endian u32 as a Uint32Array. */
export const u32 = (text) => typed(text, Uint32Array, (v, o) => v.getUint32(o, true));

/** The document as the Rust side wrote it, with every encoded array decoded. */
export function decodeDocument(raw) {
  const robot = raw.robot && {
    ...raw.robot,
    links: raw.robot.links.map((link) => ({
      name: link.name,
      spheres: f32(link.spheres),
      meshes: link.meshes.map((m) => ({ positions: f32(m.positions), indices: u32(m.indices), colour: m.colour })),
    })),
  };
  const scene = {
    ...raw.scene,
    clouds: raw.scene.clouds.map((c) => ({ ...c, points: f32(c.points) })),
    movers: raw.scene.movers ?? [],
  };
  const motions = raw.motions.map((m) => ({
    ...m, joints: f32(m.joints), poses: f32(m.poses), mover_positions: f32(m.mover_positions),
  }));
  const search = raw.search && { ...raw.search, segments: f32(raw.search.segments), costs: f32(raw.search.costs) };
  return { ...raw, robot, scene, motions, search };
}
