// UI panel: the header (title, subtitle, notes), the motion controls, toggles, the cost legend
// and the joint-value table.
import { cssGradient } from './colour_map.js';

function el(tag, attrs = {}, ...children) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k === 'class') node.className = v; else if (k in node) node[k] = v; else node.setAttribute(k, v);
  }
  node.append(...children.filter((c) => c !== null && c !== undefined));
  return node;
}

function toggle(id, label, checked, onChange, disabled = false) {
  const box = el('input', { type: 'checkbox', id, checked, disabled });
  box.addEventListener('change', () => onChange(box.checked));
  return el('label', { class: 'toggle' }, box, ` ${label}`);
}

const fmt = (v) => (Math.abs(v) >= 1e4 || (v !== 0 && Math.abs(v) < 1e-3) ? v.toExponential(3) : v.toFixed(3));

/** Builds the panel into `root`. `doc` is the decoded document; `actions` the callbacks. */
export function buildPanel(root, doc, actions) {
  root.append(el('h1', {}, doc.title));
  for (const line of doc.subtitle) root.append(el('p', { class: 'subtitle' }, line));
  if (doc.notes.length > 0) root.append(el('ul', { class: 'notes' }, ...doc.notes.map((n) => el('li', {}, n))));

  const view = { frame: null, reading: null, joints: null, slider: null, play: null };
  if (doc.motions.length > 1) {
    const select = el('select', { id: 'motion-select' }, ...doc.motions.map((m, k) => el('option', { value: String(k) }, m.label)));
    select.addEventListener('change', () => actions.setMotion(Number(select.value)));
    view.select = select;
    root.append(el('label', { class: 'row' }, 'motion ', select));
  } else if (doc.motions.length === 1) {
    root.append(el('p', { class: 'label' }, doc.motions[0].label));
  } else if (doc.robot) {
    root.append(el('p', { class: 'note' }, 'no motion: the robot is not drawn (its pose is unknown)'));
  }
  if (doc.motions.length > 0) {
    view.slider = el('input', { type: 'range', id: 'frame-slider', min: '0', max: '0', step: '1', value: '0' });
    view.slider.addEventListener('input', () => actions.setFrame(Number(view.slider.value)));
    view.play = el('button', { id: 'play', type: 'button' }, 'play');
    view.play.addEventListener('click', actions.togglePlay);
    const speed = el('select', { id: 'speed' }, ...[0.25, 0.5, 1, 2, 4, 10].map((s) => el('option', { value: String(s), selected: s === 1 }, `${s}×`)));
    speed.addEventListener('change', () => actions.setSpeed(Number(speed.value)));
    view.frame = el('span', { id: 'frame-label' });
    view.reading = el('span', { id: 'reading' });
    root.append(view.slider, el('div', { class: 'row' }, view.play, ' speed ', speed, ' ', view.frame, ' ', view.reading));
  }
  const toggles = el('div', { class: 'toggles' });
  if (doc.robot) {
    const hasMeshes = doc.robot.links.some((l) => l.meshes.length > 0);
    toggles.append(toggle('mesh-toggle', 'meshes (off: spheres)', hasMeshes, actions.setMeshes, !hasMeshes));
    if (!hasMeshes) toggles.append(el('p', { class: 'note' }, 'no meshes in this view: spheres shown'));
  }
  if (doc.motions.some((m) => m.waypoints.length > 0)) toggles.append(toggle('ghost-toggle', 'ghosts at waypoints', true, actions.setGhosts));
  if (doc.search) toggles.append(toggle('search-toggle', `search: ${doc.search.label}`, actions.searchShown, actions.setSearch));
  root.append(toggles);
  if (doc.search && actions.costRange) {
    const [lo, hi] = actions.costRange;
    root.append(el('div', { class: 'legend' },
      el('div', { class: 'bar', style: `background: ${cssGradient()}` }),
      el('div', { class: 'row spread' }, el('span', {}, fmt(lo)), el('span', {}, 'cost-to-come'), el('span', {}, fmt(hi)))));
  }
  view.joints = el('table', { id: 'joints' });
  root.append(view.joints);
  return view;
}

/** Shows the player's state: slider, labels, the play button and the joint table. */
export function showFrame(view, player) {
  if (!view.slider || !player.current) return;
  const { motion } = player.current;
  view.slider.max = String(Math.max(motion.frames - 1, 0));
  view.slider.value = String(Math.round(player.frame));
  if (view.select) view.select.value = String(player.index);
  view.play.textContent = player.playing ? 'pause' : 'play';
  const i = Math.round(player.frame);
  const collides = player.current.colliding[i] === 1;
  view.frame.textContent = `frame ${i} / ${motion.frames - 1}${collides ? ' — in collision' : ''}`;
  view.frame.classList.toggle('bad', collides);
  const r = player.reading();
  view.reading.textContent = r.kind === 'time' ? `t = ${r.value.toFixed(3)} s` : `path ${(100 * r.value).toFixed(1)} %`;
  const dof = motion.joint_names.length;
  if (view.joints.rows.length !== dof) {
    view.joints.replaceChildren(...motion.joint_names.map((n) => el('tr', {}, el('td', {}, n), el('td', { class: 'value' }))));
  }
  const lo = Math.floor(player.frame);
  const hi = Math.min(lo + 1, motion.frames - 1);
  const t = player.frame - lo;
  for (let k = 0; k < dof; k++) {
    const v = motion.joints[lo * dof + k] * (1 - t) + motion.joints[hi * dof + k] * t;
    view.joints.rows[k].cells[1].textContent = fmt(v);
  }
}
