// Settings kept per browser: the online tile URL (localStorage) and the access token.

import * as api from './api.js';
import { ui } from './store.js';
import { $ } from './util.js';

const TILE_KEY = 'usv-station-tile-url';

export function applyStoredTiles() {
  const tileUrl = localStorage.getItem(TILE_KEY);
  if (tileUrl) ui.map.setTileUrl(tileUrl);
}

export function bindSettings() {
  $('tile-url').value = localStorage.getItem(TILE_KEY) ?? '';
  $('tile-form').addEventListener('submit', (e) => {
    e.preventDefault();
    const url = $('tile-url').value.trim();
    localStorage.setItem(TILE_KEY, url);
    ui.map.setTileUrl(url);
    $('settings-status').textContent = url ? `online map: ${url}` : 'offline grid only';
  });
  $('token-form').addEventListener('submit', (e) => {
    e.preventDefault();
    api.setToken($('token').value);
    $('token').value = '';
    $('settings-status').textContent = 'token saved for this browser tab';
  });
}
