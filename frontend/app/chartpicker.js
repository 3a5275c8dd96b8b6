// The real chart: offline chart packages served by the station (`--charts DIR`,
// GET /api/charts) as a tile layer under the ramp-frame grid, and the ramp origin
// placed with a click on the map. The grid alone stays the default.

import * as api from './api.js';
import { setSetting, settings } from './settings.js';
import { ui } from './store.js';
import { $ } from './util.js';

let packages = [];
let pickingOrigin = false;

function choose(name) {
  const pkg = packages.find((p) => p.name === name) ?? null;
  ui.map.setChart(pkg);
  $('settings-status').textContent = pkg ? `offline chart: ${pkg.title}` : 'no offline chart';
}

async function loadCharts() {
  try {
    packages = await api.get('/api/charts');
  } catch {
    packages = [];
  }
  const select = $('chart-select');
  select.replaceChildren(select.options[0], ...packages.map((p) => {
    const opt = document.createElement('option');
    opt.value = p.name;
    opt.textContent = `${p.title} (${p.format}, zoom ${p.minzoom ?? '?'}-${p.maxzoom ?? '?'})`;
    return opt;
  }));
  if (packages.some((p) => p.name === settings.chart)) {
    select.value = settings.chart;
    choose(settings.chart);
  }
}

/** True while the next map click places the ramp origin. */
export function pickingOriginNow() {
  return pickingOrigin;
}

function setPicking(on) {
  pickingOrigin = on;
  const button = $('set-origin');
  button.setAttribute('aria-pressed', String(on));
  button.textContent = on ? 'Click the ramp end on the map…' : 'Set ramp origin on the map';
}

/** Move the ramp end (the scenario's origin) to `latlng`, keeping the ramp's bearing. */
export function placeOrigin(latlng) {
  setPicking(false);
  const editor = ui.editor;
  const bearing = editor.scenario.origin?.ramp_bearing_deg ?? 90;
  const origin = { lat: Number(latlng.lat.toFixed(7)), lon: Number(latlng.lng.toFixed(7)),
    ramp_bearing_deg: bearing };
  editor.scenario.origin = origin;
  ui.map.setOrigin(origin);
  editor.changed();
  $('scenario-status').textContent = `ramp origin set to ${origin.lat}, ${origin.lon}`;
}

/** Put the ramp origin where own ship's sensors place the ramp end now (lever arm applied
 * by the station's world model); refused with a clear message without an own-ship fix. */
async function originFromOwnShip() {
  try {
    const world = await api.get('/api/world');
    if (!world.own_ship || !world.ramp || world.ramp.source !== 'own_ship') {
      $('scenario-status').textContent = 'no own-ship position yet (serve --nmea, or a simulated mother ship)';
      return;
    }
    const { lat, lon, ramp_bearing_deg: bearing } = world.ramp;
    const origin = { lat: Number(lat.toFixed(7)), lon: Number(lon.toFixed(7)),
      ramp_bearing_deg: Number(bearing.toFixed(3)) };
    setPicking(false);
    ui.editor.scenario.origin = origin;
    ui.map.setOrigin(origin);
    ui.editor.changed();
  } catch (err) {
    $('scenario-status').textContent = `own ship unavailable: ${err.message ?? err}`;
  }
}

export function bindCharts() {
  $('origin-from-ship').addEventListener('click', originFromOwnShip);
  $('chart-select').addEventListener('change', (e) => {
    setSetting('chart', e.target.value);
    choose(e.target.value);
  });
  $('set-origin').addEventListener('click', () => setPicking(!pickingOrigin));
  $('map').addEventListener('centre-boat', () => ui.map.centreOnBoat());
  loadCharts();
}
