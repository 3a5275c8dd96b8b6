// Live state: the station's websocket (/ws/live) and the link status in the top bar.

import * as api from './api.js';
import { renderMission } from './mission.js';
import { onTelemetry, refreshRuns, showRun } from './runs.js';
import { emit, state, ui } from './store.js';
import { $, fmt, setPill } from './util.js';

const BOAT_POLL_MS = 1000;

async function pollBoat() {
  try {
    const boat = await api.get('/api/boat');
    const link = boat.link;
    setPill($('link-state'), link.up ? `link up${link.simulated ? ' (simulated boat)' : ''}`
      : `link down${link.error ? `: ${link.error}` : ''}`, link.up ? 'ok' : 'bad');
    $('hb-age').textContent = fmt(link.heartbeat_age_s);
    $('tm-age').textContent = fmt(link.telemetry_age_s);
    $('frames').textContent = String(link.frames ?? '–');
    $('frames-lost').textContent = link.frames_lost == null ? '–' : String(link.frames_lost);
    if (boat.boat) $('boat-state').textContent = `${boat.boat.state} (${boat.boat.mode})`;
  } catch (err) {
    setPill($('link-state'), `station unreachable`, 'bad');
  }
}

export function startPolling() {
  pollBoat();
  setInterval(pollBoat, BOAT_POLL_MS);
}

function addMessage(item) {
  const li = document.createElement('li');
  li.className = `sev-${String(item.severity).toLowerCase()}`;
  li.textContent = `${new Date(item.time).toLocaleTimeString()} ${item.severity}: ${item.text}`;
  const list = $('messages');
  list.prepend(li);
  while (list.children.length > 20) list.lastChild.remove();
}

export function connectLive(delay = 500) {
  const url = `${location.protocol === 'https:' ? 'wss' : 'ws'}://${location.host}/ws/live`;
  const ws = new WebSocket(url);
  ws.onopen = () => setPill($('live-state'), 'live: connected', 'ok');
  ws.onmessage = (ev) => {
    const msg = JSON.parse(ev.data);
    handleLive(msg.type, msg.data);
  };
  ws.onclose = () => {
    const next = Math.min(delay * 2, 5000);
    setPill($('live-state'), `live: reconnecting in ${(next / 1000).toFixed(1)} s`, 'bad');
    setTimeout(() => connectLive(next), next);
  };
}

function handleLive(type, data) {
  switch (type) {
    case 'hello':
      if (data.telemetry) onTelemetry(data.telemetry, false);
      if (data.run != null && (!state.shown || state.shown.id !== data.run)) {
        showRun(data.run, { live: true });
      }
      (data.status ?? []).forEach(addMessage);
      break;
    case 'telemetry':
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
