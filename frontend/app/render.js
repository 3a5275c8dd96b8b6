// Drawing: telemetry is buffered as it arrives (store.pending) and drawn once per
// animation frame; the charts redraw at most twice a second.

import { pending, state, ui, emit } from './store.js';
import { $, fmt } from './util.js';

const CHART_EVERY_MS = 500;
let frameRequested = false;
let chartTimer = null;
let lastChartAt = -Infinity;
let firstDrawn = false;
let firstLiveDrawn = false;

export function requestRender() {
  if (frameRequested) return;
  frameRequested = true;
  requestAnimationFrame(render);
}

function render() {
  frameRequested = false;
  const { map, charts } = ui;
  if (pending.rows.length) {
    const rows = pending.rows;
    pending.rows = [];
    map.appendTrack(rows);
    charts.appendReal(rows);
    scheduleCharts();
    $('track-points').textContent = String(map.trackLatLngs.length);
  }
  if (pending.boat && state.telemetry) {
    pending.boat = false;
    drawBoat(state.telemetry);
  }
  if (pending.time) {
    pending.time = false;
    map.setDisplayTime(state.displayT);
    $('time').value = String(state.displayT);
    $('time-out').textContent = fmt(state.displayT);
    emit('time', state.displayT);
  }
}

function drawBoat(row) {
  ui.map.setBoat(row);
  emit('boat-drawn', row);
  if (!firstDrawn) {
    firstDrawn = true;
    performance.mark('first-telemetry-drawn');
  }
  if (pending.fromLive && !firstLiveDrawn) {
    firstLiveDrawn = true;
    performance.mark('first-live-telemetry-drawn');
  }
}

/** Redraw the charts now if they have not been drawn for a while, else a little later. */
export function scheduleCharts() {
  if (chartTimer !== null) return;
  const wait = Math.max(0, lastChartAt + CHART_EVERY_MS - performance.now());
  chartTimer = setTimeout(() => {
    chartTimer = null;
    lastChartAt = performance.now();
    ui.charts.flush();
  }, wait);
}

export function setDisplayTime(t) {
  state.displayT = Math.max(0, t);
  pending.time = true;
  requestRender();
}

/** Stop following the live run (the operator took the time slider). */
export function setFollow(follow) {
  state.follow = follow;
  $('follow').checked = follow;
}
