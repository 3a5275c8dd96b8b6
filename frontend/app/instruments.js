// The boat card's instruments: the boat's latest reported state, each marked with
// its age (grey, "n s old") once older than STALE_S, so a value kept through a
// link outage is never mistaken for a current one.

import { on, state } from './store.js';
import { settings, speedIn } from './settings.js';
import { $, fmt } from './util.js';

export const STALE_S = 2;
const TICK_MS = 250;
// MAVLink GPS_FIX_TYPE
const FIX = ['no GPS', 'no fix', '2D', '3D', 'DGPS', 'RTK float', 'RTK fixed', 'static', 'PPP'];
const TELEMETRY = ['x', 'y', 'sog', 'cog', 'heading', 'xte', 'slip', 'battery', 'fix',
  'sats', 'hdop', 'thrust'];
const LINK = ['lost', 'rssi'];

/** performance.now() when each instrument's value was current. */
const currentAt = {};

function mark(names, at) {
  for (const name of names) currentAt[name] = at;
}

/** Seconds behind (+) or ahead (-) of the plan: run time minus the plan's time at the
 * point of the planned path nearest to the boat (position linear in time per leg). */
export function scheduleSlip(waypoints, x, y, runT) {
  let best = Infinity;
  let tPlan = null;
  for (let i = 1; i < waypoints.length; i++) {
    const a = waypoints[i - 1];
    const b = waypoints[i];
    const dx = b.x - a.x;
    const dy = b.y - a.y;
    const len2 = dx * dx + dy * dy;
    const f = len2 > 0 ? Math.min(Math.max(((x - a.x) * dx + (y - a.y) * dy) / len2, 0), 1) : 0;
    const d = Math.hypot(a.x + f * dx - x, a.y + f * dy - y);
    if (d < best) {
      best = d;
      tPlan = a.t + f * (b.t - a.t);
    }
  }
  return tPlan === null ? null : runT - tPlan;
}

function showTelemetry(row) {
  $('boat-x').textContent = fmt(row.x);
  $('boat-y').textContent = fmt(row.y);
  $('boat-speed').textContent = fmt(speedIn(row.speed), 2);
  $('boat-cog').textContent = fmt(row.course_deg, 0);
  $('boat-heading').textContent = fmt(row.ramp_heading_deg, 0);
  $('boat-compass').textContent = fmt(row.heading_deg, 0);
  $('boat-xte').textContent = fmt(row.cross_track_m, 1);
  $('boat-battery').textContent = fmt(row.battery_v, 2);
  $('boat-fix').textContent = row.fix_type == null ? '–' : (FIX[row.fix_type] ?? String(row.fix_type));
  $('boat-sats').textContent = row.satellites == null ? '–' : String(row.satellites);
  $('boat-hdop').textContent = fmt(row.hdop, 1);
  $('boat-thrust-l').textContent = row.thrust_left == null ? '–' : fmt(row.thrust_left * 100, 0);
  $('boat-thrust-r').textContent = row.thrust_right == null ? '–' : fmt(row.thrust_right * 100, 0);
  const shown = state.shown;
  const plan = state.plan?.plan;
  let slip = null;
  if (shown && shown.id === row.run && shown.t0 !== null && plan && row.x != null) {
    slip = scheduleSlip(plan.waypoints, row.x, row.y, row.boat_time - shown.t0);
  }
  const el = $('boat-slip');
  el.textContent = slip === null ? '–' : `${slip >= 0 ? '+' : ''}${slip.toFixed(1)}`;
}

/** Link counters from GET /api/boat (`link`), current `ageS` seconds ago. */
export function showLink(link, ageS = 0) {
  $('boat-lost').textContent = link.frames_lost == null ? '–' : String(link.frames_lost);
  const rssi = link.radio?.rssi ?? link.rssi;
  $('boat-rssi').textContent = rssi == null ? 'not reported' : String(rssi);
  mark(LINK, performance.now() - ageS * 1000);
}

/** Grey every instrument older than STALE_S and say how old it is. */
function tick() {
  const now = performance.now();
  for (const div of document.querySelectorAll('#instruments [data-instrument]')) {
    const name = div.dataset.instrument;
    const at = currentAt[name];
    if (at === undefined) continue;
    const age = (now - at) / 1000;
    const stale = age > STALE_S;
    div.classList.toggle('stale', stale);
    let tag = div.querySelector('.age');
    if (stale) {
      if (!tag) {
        tag = document.createElement('small');
        tag.className = 'age';
        div.querySelector('dd').append(tag);
      }
      tag.textContent = ` ${age < 100 ? age.toFixed(1) : Math.round(age)} s old`;
      div.title = `last reported ${age.toFixed(1)} s ago`;
    } else if (tag) {
      tag.remove();
      div.removeAttribute('title');
    }
  }
}

export function bindInstruments() {
  on('boat-drawn', (row) => {
    showTelemetry(row);
  });
  // the age of the newest row, from when it arrived (live) or the station's age (hello)
  on('telemetry-received', ({ ageS }) => mark(TELEMETRY, performance.now() - ageS * 1000));
  on('live:heartbeat', () => mark(['state'], performance.now()));
  on('units', () => { if (state.telemetry) showTelemetry(state.telemetry); });
  setInterval(tick, TICK_MS);
  document.querySelectorAll('.speed-unit').forEach((el) => { el.textContent = settings.unitLabel; });
}
