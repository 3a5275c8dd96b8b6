// The alerts panel: the station's alerts (GET /api/alerts, then {"type": "alert"} on
// the websocket) with severity colours, a sound for new warnings (mutable under
// Settings), acknowledge, and the history. The newest unacknowledged alert is in a
// role="alert" region, so screen readers announce it. The console adds one alert of
// its own: the station itself unreachable (no websocket), which the station cannot say.

import * as api from './api.js';
import { on } from './store.js';
import { settings } from './settings.js';
import { $ } from './util.js';

const RANK = { advisory: 0, caution: 1, warning: 2 };
const alerts = new Map(); // id -> alert
let localId = 0;
let audio = null;

function beep() {
  if (!settings.sound) return;
  try {
    audio = audio ?? new AudioContext();
    const osc = audio.createOscillator();
    const gain = audio.createGain();
    osc.frequency.value = 880;
    gain.gain.value = 0.15;
    osc.connect(gain).connect(audio.destination);
    osc.start();
    osc.stop(audio.currentTime + 0.35);
  } catch {
    // no audio device: the panel still shows the warning
  }
}

function time(iso) {
  return new Date(iso).toLocaleTimeString([], { hour12: false });
}

function render() {
  const all = [...alerts.values()].sort((a, b) => b.time.localeCompare(a.time));
  const open = all.filter((a) => !a.acknowledged)
    .sort((a, b) => RANK[b.level] - RANK[a.level] || b.time.localeCompare(a.time));
  const now = $('alert-now');
  const top = open[0];
  now.className = `alert-now${top ? ` level-${top.level}` : ''}`;
  now.textContent = top ? `${top.level.toUpperCase()}: ${top.message}` : '';
  $('alerts-count').textContent = open.length ? `${open.length} open` : 'none open';
  $('alerts-ack-all').disabled = open.length === 0;
  const list = $('alerts-list');
  list.replaceChildren(...all.slice(0, 100).map((a) => {
    const li = document.createElement('li');
    li.className = `level-${a.level}${a.acknowledged ? ' acked' : ''}`;
    li.dataset.kind = a.kind;
    li.textContent = `${time(a.time)} ${a.level}: ${a.message}`;
    if (!a.acknowledged) {
      const ack = document.createElement('button');
      ack.type = 'button';
      ack.className = 'icon';
      ack.textContent = 'Ack';
      ack.setAttribute('aria-label', `acknowledge: ${a.message}`);
      ack.addEventListener('click', () => acknowledge(a));
      li.append(' ', ack);
    }
    return li;
  }));
}

async function acknowledge(alert) {
  if (alert.local) { // the console's own: the station has no record of it
    alert.acknowledged = true;
    render();
    return;
  }
  try {
    alerts.set(alert.id, await api.post(`/api/alerts/${alert.id}/ack`));
  } catch (err) {
    $('alert-now').textContent = `cannot acknowledge: ${err.message}`;
    return;
  }
  render();
}

function received(alert, { fresh }) {
  const known = alerts.get(alert.id);
  alerts.set(alert.id, alert);
  if (fresh && !known && alert.level === 'warning' && !alert.acknowledged) beep();
  render();
}

/** An alert raised by the console itself (the station unreachable). */
export function localAlert(level, kind, message) {
  localId += 1;
  received({ id: `local-${localId}`, time: new Date().toISOString(), level, kind, message,
    target_id: null, run_id: null, acknowledged: false, local: true }, { fresh: true });
}

export function clearLocal(kind) {
  for (const a of alerts.values()) {
    if (a.local && a.kind === kind) a.acknowledged = true;
  }
  render();
}

export async function loadAlerts() {
  try {
    for (const a of await api.get('/api/alerts')) received(a, { fresh: false });
  } catch (err) {
    if (err.status !== 404) $('alert-now').textContent = `alerts unavailable: ${err.message}`;
  }
}

export function bindAlerts() {
  on('live:alert', (a) => received(a, { fresh: true }));
  $('alerts-ack-all').addEventListener('click', () => {
    for (const a of alerts.values()) if (!a.acknowledged) acknowledge(a);
  });
  $('alerts-history').addEventListener('click', (e) => {
    const list = $('alerts-list');
    list.hidden = !list.hidden;
    e.target.setAttribute('aria-expanded', String(!list.hidden));
  });
  render();
}
