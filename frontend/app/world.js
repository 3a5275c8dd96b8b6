// The live world on the map and in the Targets card (issue 25): the ramp where the own ship
// puts it now (the map's frame moves with it: plan, boat, track and targets are drawn in
// that same ship-fixed frame), the mother ship's hull, and every target with its symbol,
// COG/SOG vector and a row of the table (DCPA, TCPA, predicted clearance, age), dangerous
// ones red. GET /api/world at start, then {"type": "world"} and {"type": "monitor"} events.

import * as api from './api.js';
import { unacknowledgedTargets } from './alerts.js';
import { targetClass, targetName } from './map.js';
import { on, state, ui } from './store.js';
import { $, fmt } from './util.js';

const world = { snapshot: null, monitor: null };

/** The latest world snapshot (for tests and the curious). */
export const worldSnapshot = () => world.snapshot;

/** DCPA (m) and TCPA (s) of a target at relative position p with relative velocity w (the
 * vector form the station's monitor uses: TCPA = -(p.w)/|w|^2, DCPA = |p x w|/|w|). */
export function dcpaTcpa(px, py, wx, wy) {
  const w2 = wx * wx + wy * wy;
  if (w2 < 1e-12) return [Math.hypot(px, py), 0];
  return [Math.abs(px * wy - py * wx) / Math.sqrt(w2), -(px * wx + py * wy) / w2];
}

/** The boat's velocity relative to the ramp (ramp axes) from a telemetry row. */
function boatRelativeVelocity(row, ramp) {
  if (!row || row.speed == null || row.course_deg == null || !ui.map) return null;
  const c = (row.course_deg * Math.PI) / 180;
  const [vx, vy] = ui.map.frame.enuToRamp(row.speed * Math.sin(c), row.speed * Math.cos(c));
  return [vx - (ramp?.vx ?? 0), vy - (ramp?.vy ?? 0)];
}

/** One row per target: the monitor's values during a run (to the boat along its plan), else
 * DCPA/TCPA of the present motion to the boat (or to the ship without a boat). */
export function targetRows(snapshot, monitor, telemetry) {
  const assessed = new Map((monitor?.targets ?? []).map((t) => [t.id, t]));
  const margin = monitor?.margin_m ?? null;
  const boat = telemetry && telemetry.x != null ? telemetry : null;
  const bv = boat ? boatRelativeVelocity(boat, snapshot.ramp) : null;
  const rows = snapshot.targets.map((t) => {
    const m = assessed.get(t.id);
    let dcpa;
    let tcpa;
    if (m) {
      dcpa = m.dcpa_m;
      tcpa = m.tcpa_s;
    } else {
      const [ox, oy] = boat ? [boat.x, boat.y] : [0, 0];
      const [ux, uy] = bv ?? [0, 0];
      [dcpa, tcpa] = dcpaTcpa(t.x - ox, t.y - oy, t.rvx - ux, t.rvy - uy);
    }
    const clearance = m ? m.min_clearance_m : null;
    return { target: t, dcpa, tcpa, clearance, danger: clearance != null && margin != null
      && clearance < margin };
  });
  const key = (r) => (r.clearance ?? Infinity);
  const ahead = (r) => (r.tcpa > 0 ? r.tcpa : Infinity);
  return rows.sort((a, b) => key(a) - key(b) || ahead(a) - ahead(b) || a.dcpa - b.dcpa);
}

function cell(text, cls) {
  const td = document.createElement('td');
  td.textContent = text;
  if (cls) td.className = cls;
  return td;
}

function renderTargets() {
  const snapshot = world.snapshot;
  if (!snapshot) return;
  const shown = snapshot.targets.filter((t) => t.source !== 'manual');
  const rows = targetRows({ ...snapshot, targets: shown }, world.monitor, state.telemetry);
  const danger = new Set(rows.filter((r) => r.danger).map((r) => r.target.id));
  $('targets-count').textContent = `${shown.length} tracked${danger.size ? `, ${danger.size} `
    + 'dangerous' : ''}`;
  $('target-rows').replaceChildren(...rows.map((r) => {
    const t = r.target;
    const tr = document.createElement('tr');
    tr.dataset.target = t.id;
    tr.className = [r.danger ? 'danger' : '', t.lost ? 'lost' : ''].filter(Boolean).join(' ');
    const name = cell(targetName(t));
    name.title = `${t.id}${t.mmsi ? `, MMSI ${t.mmsi}` : ''}, SOG ${fmt(t.speed, 1)} m/s, `
      + `COG ${fmt(t.course_deg, 0)}°`;
    tr.append(name, cell(targetClass(t)), cell(fmt(r.dcpa, 1), 'dcpa'),
      cell(r.tcpa > 0 ? fmt(r.tcpa, 0) : 'past', 'tcpa'),
      cell(r.clearance == null ? '–' : fmt(r.clearance, 1), 'clearance'),
      cell(t.lost ? `${fmt(t.age_s, 0)} lost` : fmt(t.age_s, 0), 'age'));
    return tr;
  }));
  ui.map.setTargets(snapshot.targets, { minutes: Number($('vector-min').value) || 3, danger,
    flash: unacknowledgedTargets() });
}

function renderOwnShip(snapshot) {
  const own = snapshot.own_ship;
  const el = $('own-ship-status');
  if (!own) {
    el.textContent = snapshot.ramp?.source === 'origin'
      ? 'no own-ship position: the ramp is the scenario origin' : '';
    el.className = 'result';
    return;
  }
  el.textContent = own.stale
    ? `own ship: no fix for ${fmt(own.age_s, 0)} s, the ramp is dead-reckoned (stale)`
    : `own ship: ${fmt(own.speed, 1)} m/s, course ${fmt(own.course_deg, 0)}°, fix `
      + `${fmt(own.age_s, 1)} s old`;
  el.className = own.stale ? 'warning' : 'result';
}

/** A world snapshot (`GET /api/world` or a `world` event): frame, ship, targets. */
export function showWorld(snapshot) {
  world.snapshot = snapshot;
  ui.map.setShip(snapshot.ship ?? null);
  ui.map.setRampPose(snapshot.ramp);
  ui.charts.setRampMotion(snapshot.ramp, ui.map.frame);
  renderOwnShip(snapshot);
  renderTargets();
}

export async function loadWorld() {
  try {
    showWorld(await api.get('/api/world'));
  } catch (err) {
    if (err.status !== 404) $('own-ship-status').textContent = `world unavailable: ${err.message}`;
  }
}

export function bindWorld() {
  on('live:world', showWorld);
  on('live:monitor', (m) => {
    world.monitor = m;
    state.monitor = m;
    renderTargets();
  });
  on('live:run', (r) => {
    if (r.state !== 'active') {
      world.monitor = null;
      state.monitor = null;
    }
  });
  on('alerts', () => renderTargets());
  $('vector-min').addEventListener('change', renderTargets);
  $('orientation').addEventListener('change', (e) => ui.map.setOrientation(e.target.value));
  $('keep-ship').addEventListener('change', (e) => ui.map.setKeepShip(e.target.checked));
}
