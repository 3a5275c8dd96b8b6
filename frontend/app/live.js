// Live state: the station's websocket (/ws/live) and the link status in the top bar.

import { clearLocal, loadAlerts, localAlert } from './alerts.js';
import * as api from './api.js';
import { showLink } from './instruments.js';
import { renderMission } from './mission.js';
import { loadWorld } from './world.js';
import { onTelemetry, refreshRuns, showRun } from './runs.js';
import { emit, state, ui } from './store.js';
import { $, fmt, setPill } from './util.js';

// The live websocket carries telemetry, heartbeats (with the link's counters), link
// changes and alerts; GET /api/boat is read at start and then only every BOAT_POLL_MS.
const BOAT_POLL_MS = 30000;
const AGE_TICK_MS = 500;
const ages = { hb: null, tm: null }; // performance.now() of the last heartbeat / telemetry

/** The boat's reported state and the mission it holds (usv-link 2 USV_MISSION_STATE). */
function boatText(b) {
  return b.mission_id ? `${b.state} (mission ${b.mission_id})` : b.state;
}

/** The link pill from a link status (GET /api/boat `link`, every heartbeat's `link`): an
 *  unsigned link says so plainly for as long as it lasts ("unsigned link: ..."). */
function showLinkState(link) {
  setPill($('link-state'), link.up ? `link up${link.simulated ? ' (simulated boat)' : ''}`
    : `link down${link.error ? `: ${link.error}` : ''}`, link.up ? 'ok' : 'bad');
  if (link.warning) setPill($('link-state'), `${$('link-state').textContent}: ${link.warning}`, 'bad');
}

async function pollBoat() {
  try {
    const boat = await api.get('/api/boat');
    const link = boat.link;
    showLinkState(link);
    const now = performance.now();
    if (link.heartbeat_age_s != null) ages.hb = now - link.heartbeat_age_s * 1000;
    if (link.telemetry_age_s != null) ages.tm = now - link.telemetry_age_s * 1000;
    showAges();
    showCounters(link);
    if (boat.boat) $('boat-state').textContent = boatText(boat.boat);
  } catch (err) {
    setPill($('link-state'), `station unreachable`, 'bad');
  }
}

function showCounters(link) {
  $('frames').textContent = String(link.frames ?? '–');
  $('frames-lost').textContent = link.frames_lost == null ? '–' : String(link.frames_lost);
  showLink(link);
}

function showAges() {
  const now = performance.now();
  $('hb-age').textContent = ages.hb === null ? '–' : fmt((now - ages.hb) / 1000);
  $('tm-age').textContent = ages.tm === null ? '–' : fmt((now - ages.tm) / 1000);
}

export function startPolling() {
  pollBoat();
  setInterval(pollBoat, BOAT_POLL_MS);
  setInterval(showAges, AGE_TICK_MS);
}

function addMessage(item) {
  const li = document.createElement('li');
  li.className = `sev-${String(item.severity).toLowerCase()}`;
  li.textContent = `${new Date(item.time).toLocaleTimeString()} ${item.severity}: ${item.text}`;
  const list = $('messages');
  list.prepend(li);
  while (list.children.length > 20) list.lastChild.remove();
}

let lostStation = false;

export function connectLive(delay = 500) {
  const url = `${location.protocol === 'https:' ? 'wss' : 'ws'}://${location.host}/ws/live`;
  const ws = new WebSocket(url);
  ws.onopen = () => {
    setPill($('live-state'), 'live: connected', 'ok');
    if (lostStation) {
      lostStation = false;
      clearLocal('station_lost');
      pollBoat();
    }
  };
  ws.onmessage = (ev) => {
    const msg = JSON.parse(ev.data);
    handleLive(msg.type, msg.data);
  };
  ws.onclose = () => {
    if (!lostStation) {
      lostStation = true;
      localAlert('warning', 'station_lost', 'no live connection to the station: the values '
        + 'shown are not updated');
    }
    const next = Math.min(delay * 2, 5000);
    setPill($('live-state'), `live: reconnecting in ${(next / 1000).toFixed(1)} s`, 'bad');
    setTimeout(() => connectLive(next), next);
  };
}

function handleLive(type, data) {
  switch (type) {
    case 'hello':
      if (data.telemetry) {
        emit('telemetry-received', { ageS: data.link?.telemetry_age_s ?? 0 });
        onTelemetry(data.telemetry, false);
      }
      loadAlerts();
      loadWorld();
      if (data.boat) $('boat-state').textContent = boatText(data.boat);
      if (data.run != null && (!state.shown || state.shown.id !== data.run)) {
        showRun(data.run, { live: true });
      }
      (data.status ?? []).forEach(addMessage);
      break;
    case 'telemetry':
      ages.tm = performance.now();
      emit('telemetry-received', { ageS: 0 });
      onTelemetry(data, true);
      break;
    case 'mission':
      if (!state.mission || state.mission.id === data.id || data.state === 'uploading') {
        renderMission(data);
      }
      break;
    case 'run':
      refreshRuns();
      if (data.state === 'active' && state.follow) {
        if (!state.shown || state.shown.id !== data.id) showRun(data.id, { live: true });
      } else if (state.shown && state.shown.id === data.id) {
        state.shown.live = false;
      }
      break;
    case 'link':
      setPill($('link-state'), data.up ? 'link up' : `link down: ${data.reason ?? ''}`,
        data.up ? 'ok' : 'bad');
      if (data.up) ages.hb = performance.now();
      break;
    case 'heartbeat':
      ages.hb = performance.now();
      $('boat-state').textContent = boatText(data);
      if (data.link) {
        showLinkState(data.link);
        showCounters(data.link);
      }
      break;
    case 'status':
      addMessage(data);
      break;
    case 'scenario':
      ui.editor.reloadIfClean();
      break;
    default:
      break;
  }
  emit(`live:${type}`, data);
}
