// The operator console's start-up: makes the map, charts and scenario editor, binds
// each card's controls (one module per concern, one store of state in store.js) and
// connects to the station's HTTP API and live websocket (/ws/live).

import { bindAlerts, setRepeatMs, sound } from './alerts.js';
import * as api from './api.js';
import { bindCharts, pickingOriginNow, placeOrigin } from './chartpicker.js';
import { TelemetryCharts } from './charts.js';
import { bindInstruments } from './instruments.js';
import { connectLive, startPolling } from './live.js';
import { ConsoleMap, planPositionAt } from './map.js';
import { bindMissionControls, renderMission } from './mission.js';
import { bindPlanControls, showPlan, updateStale } from './plan.js';
import { bindReplans, loadReplans } from './replans.js';
import { refreshRuns } from './runs.js';
import { ScenarioEditor } from './scenario.js';
import { applyStoredTiles, bindSettings } from './settings.js';
import { state, ui } from './store.js';
import { bindShortcuts } from './shortcuts.js';
import { bindTimebar } from './timebar.js';
import { $, nextTask, showError } from './util.js';
import { bindWorld, loadWorld, worldSnapshot } from './world.js';

async function linkViser() {
  const link = $('viser-link');
  try {
    const health = await api.get('/api/health');
    if (health.viser_port) {
      link.href = '/3d/'; // viser, served by the station behind the same token
      link.removeAttribute('aria-disabled');
      link.title = '3D view (viser) at /3d/';
    } else {
      link.textContent = '3D view: not running';
    }
  } catch {
    link.textContent = '3D view: unknown';
  }
}

/** After a reload: the newest finished plan and the newest mission. */
async function restore() {
  try {
    const [plans, missions] = await Promise.all([api.get('/api/plans'), api.get('/api/missions')]);
    const done = plans.filter((p) => p.status === 'done')
      .sort((a, b) => a.created_at.localeCompare(b.created_at));
    if (done.length && !state.plan) showPlan(await api.get(`/api/plans/${done[done.length - 1].id}`));
    const latest = [...missions].sort((a, b) => a.created_at.localeCompare(b.created_at)).pop();
    if (latest && !state.mission) renderMission(latest);
  } catch (err) {
    showError('plan', err);
  }
  refreshRuns();
}

async function main() {
  api.adoptTokenFromUrl();
  await nextTask();
  ui.map = new ConsoleMap($('map'), {
    onClick: (x, y, ll) => (pickingOriginNow() ? placeOrigin(ll) : ui.editor.mapClicked(x, y)),
    onStartMoved: (x, y) => ui.editor.moveStart(x, y),
    onObstacleMoved: (i, x, y) => ui.editor.moveObstacle(i, x, y),
  });
  await nextTask();
  ui.charts = new TelemetryCharts($('chart-heading'), $('chart-speed'));
  await nextTask();
  ui.editor = new ScenarioEditor({
    map: ui.map,
    centre: () => ui.map.centreRamp(),
    onChange: () => updateStale(),
  });
  applyStoredTiles();
  bindPlanControls();
  bindMissionControls();
  bindTimebar();
  bindSettings();
  bindInstruments();
  bindAlerts();
  bindWorld();
  bindReplans();
  bindShortcuts();
  bindCharts();
  connectLive();
  await ui.editor.load({ fit: true });
  await loadWorld();
  startPolling();
  linkViser();
  restore();
  loadReplans();
}

// for tests and the curious: the map, the store, the alert sound
window.usvConsole = {
  get map() { return ui.map; },
  get state() { return state; },
  get world() { return worldSnapshot(); },
  planPositionAt,
  sound,
  setAlertRepeatMs: setRepeatMs,
};

main();
