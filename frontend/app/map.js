// The map: Leaflet in WGS-84 with everything placed from the ramp frame through
// geo.js. Default base layer: a ramp-frame grid drawn locally (no tiles, works
// offline); an online tile URL can be added under Settings.

import * as L from 'leaflet';
import { RampFrame } from './geo.js';

const GRID_STEPS_M = [1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000, 10000];
const GRID_MIN_PX = 70;
const RAMP_LENGTH_M = 6;
const RAMP_WIDTH_M = 3;
// planned-speed colour scale (low -> high), perceptually ordered
const SPEED_STOPS = ['#30123b', '#4662d7', '#1ae4b6', '#a2fc3c', '#faba39', '#e4460a'];

/** Colour of `v` on the speed scale between vmin and vmax. */
export function speedColour(v, vmin, vmax) {
  const f = vmax > vmin ? Math.min(Math.max((v - vmin) / (vmax - vmin), 0), 1) : 0.5;
  const pos = f * (SPEED_STOPS.length - 1);
  const i = Math.min(Math.floor(pos), SPEED_STOPS.length - 2);
  const a = hexRgb(SPEED_STOPS[i]);
  const b = hexRgb(SPEED_STOPS[i + 1]);
  const w = pos - i;
  const c = a.map((ch, k) => Math.round(ch + (b[k] - ch) * w));
  return `rgb(${c[0]}, ${c[1]}, ${c[2]})`;
}

function hexRgb(hex) {
  return [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16));
}

/** Position on a plan at time t (linear in time between waypoints, paper 000 eq. 9). */
export function planPositionAt(waypoints, t) {
  if (!waypoints || waypoints.length === 0) return null;
  if (t <= waypoints[0].t) return waypoints[0];
  for (let i = 1; i < waypoints.length; i++) {
    const a = waypoints[i - 1];
    const b = waypoints[i];
    if (t <= b.t) {
      const f = b.t > a.t ? (t - a.t) / (b.t - a.t) : 1;
      return { x: a.x + (b.x - a.x) * f, y: a.y + (b.y - a.y) * f, t };
    }
  }
  return waypoints[waypoints.length - 1];
}

/** R_l = R_obs + D_USV + R_c (paper 000 eq. 7). */
export function inflatedRadius(scenario, o) {
  return o.radius + scenario.vessel.length + scenario.vessel.compensation_radius;
}

function fmtM(v) {
  return `${Math.round(v * 10) / 10}`;
}

/** The ramp-frame grid: a canvas in its own pane, redrawn on every view change. */
const RampGrid = L.Layer.extend({
  initialize(getFrame) {
    this._getFrame = getFrame;
  },

  onAdd(map) {
    if (!map.getPane('gridPane')) {
      const pane = map.createPane('gridPane');
      pane.style.zIndex = 250;
      pane.style.pointerEvents = 'none';
    }
    this._canvas = L.DomUtil.create('canvas', 'ramp-grid', map.getPane('gridPane'));
    this.redraw();
  },

  onRemove() {
    L.DomUtil.remove(this._canvas);
    this._canvas = null;
  },

  getEvents() {
    return { move: this.redraw, zoomend: this.redraw, resize: this.redraw, viewreset: this.redraw };
  },

  redraw() {
    const map = this._map;
    const frame = this._getFrame();
    if (!map || !this._canvas || !frame) return this;
    const size = map.getSize();
    const dpr = window.devicePixelRatio || 1;
    const canvas = this._canvas;
    canvas.width = Math.round(size.x * dpr);
    canvas.height = Math.round(size.y * dpr);
    canvas.style.width = `${size.x}px`;
    canvas.style.height = `${size.y}px`;
    L.DomUtil.setPosition(canvas, map.containerPointToLayerPoint([0, 0]));
    const ctx = canvas.getContext('2d');
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);

    const corners = [[0, 0], [size.x, 0], [0, size.y], [size.x, size.y]].map((p) => {
      const ll = map.containerPointToLatLng(p);
      return frame.toRamp(ll.lat, ll.lng);
    });
    const xs = corners.map((c) => c[0]);
    const ys = corners.map((c) => c[1]);
    const [x0, x1, y0, y1] = [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)];
    const metresPerPx = Math.hypot(x1 - x0, y1 - y0) / Math.hypot(size.x, size.y);
    const step = GRID_STEPS_M.find((s) => s / metresPerPx >= GRID_MIN_PX) ?? 10000;
    const px = (x, y) => {
      const [lat, lon] = frame.toLatLon(x, y);
      return map.latLngToContainerPoint([lat, lon]);
    };

    ctx.font = '11px system-ui, sans-serif';
    ctx.lineWidth = 1;
    const drawLine = (a, b, label, isX) => {
      const p = px(...a);
      const q = px(...b);
      ctx.strokeStyle = label === '0' ? 'rgba(20, 50, 80, 0.55)' : 'rgba(20, 50, 80, 0.18)';
      ctx.beginPath();
      ctx.moveTo(p.x, p.y);
      ctx.lineTo(q.x, q.y);
      ctx.stroke();
      const clipped = clipSegment(p, q, size);
      if (!clipped) return;
      // x lines are labelled where they leave the bottom, y lines at the left
      const [u, v] = clipped;
      const at = isX ? (u.y > v.y ? u : v) : (u.x < v.x ? u : v);
      const text = `${isX ? 'x' : 'y'} ${label} m`;
      const w = ctx.measureText(text).width;
      const tx = Math.min(Math.max(at.x + 3, 2), size.x - w - 2);
      const ty = Math.min(Math.max(at.y - 4, 12), size.y - 4);
      ctx.fillStyle = 'rgba(20, 50, 80, 0.75)';
      ctx.fillText(text, tx, ty);
    };
    for (let x = Math.ceil(x0 / step) * step; x <= x1; x += step) {
      drawLine([x, y0], [x, y1], fmtM(x), true);
    }
    for (let y = Math.ceil(y0 / step) * step; y <= y1; y += step) {
      drawLine([x0, y], [x1, y], fmtM(y), false);
    }
    return this;
  },
});

/** The part of segment p-q inside the rectangle [0, size], or null (Liang-Barsky). */
function clipSegment(p, q, size) {
  let t0 = 0;
  let t1 = 1;
  const dx = q.x - p.x;
  const dy = q.y - p.y;
  const checks = [[-dx, p.x], [dx, size.x - p.x], [-dy, p.y], [dy, size.y - p.y]];
  for (const [pp, qq] of checks) {
    if (pp === 0) {
      if (qq < 0) return null;
    } else {
      const r = qq / pp;
      if (pp < 0) t0 = Math.max(t0, r);
      else t1 = Math.min(t1, r);
    }
  }
  if (t0 > t1) return null;
  return [L.point(p.x + t0 * dx, p.y + t0 * dy), L.point(p.x + t1 * dx, p.y + t1 * dy)];
}

function boatIcon() {
  return L.divIcon({
    className: 'boat-marker',
    iconSize: [28, 28],
    iconAnchor: [14, 14],
    html: '<svg class="boat-glyph" viewBox="-14 -14 28 28" width="28" height="28" aria-hidden="true">'
      + '<path d="M0,-12 L7,9 L0,5 L-7,9 Z" fill="#c53030" stroke="#fff" stroke-width="1.5"/></svg>',
  });
}

function replayIcon() {
  return L.divIcon({
    className: 'replay-boat',
    iconSize: [28, 28],
    iconAnchor: [14, 14],
    html: '<svg class="boat-glyph" viewBox="-14 -14 28 28" width="28" height="28" aria-hidden="true">'
      + '<path d="M0,-12 L7,9 L0,5 L-7,9 Z" fill="none" stroke="#c53030" stroke-width="2"/></svg>',
  });
}

function handleIcon(label, cls) {
  return L.divIcon({ className: `map-handle ${cls}`, iconSize: [22, 22], iconAnchor: [11, 11],
    html: `<span>${label}</span>` });
}

export class ConsoleMap {
  /**
   * @param {HTMLElement} el
   * @param {{onClick(x, y), onStartMoved(x, y), onObstacleMoved(i, x, y)}} handlers
   */
  constructor(el, handlers) {
    this.handlers = handlers;
    this.frame = new RampFrame(0, 0, 90);
    this.hasOrigin = false;
    this.horizon = 120;
    this.displayT = 0;
    this.map = L.map(el, {
      zoomSnap: 0.25,
      zoomDelta: 0.5,
      minZoom: 10,
      maxZoom: 24,
      zoomAnimation: false,
      fadeAnimation: false,
      markerZoomAnimation: false,
      keyboard: true,
      attributionControl: true,
      zoomControl: false,
    });
    L.control.zoom({ position: 'topright' }).addTo(this.map);
    this.map.attributionControl.setPrefix(false);
    this.grid = new RampGrid(() => this.frame);
    this.baseLayers = { 'Ramp-frame grid (offline)': this.grid };
    this.grid.addTo(this.map);
    L.control.scale({ metric: true, imperial: false, maxWidth: 150, position: 'bottomright' }).addTo(this.map);

    this.rampLayer = L.layerGroup().addTo(this.map);
    this.obstacleLayer = L.layerGroup().addTo(this.map);
    this.planLayer = L.layerGroup().addTo(this.map);
    this.smoothedLayer = L.layerGroup().addTo(this.map);
    this.trackLine = L.polyline([], { color: '#c53030', weight: 3, className: 'real-track',
      interactive: false });
    this.trackLayer = L.layerGroup([this.trackLine]).addTo(this.map);
    this.boatLayer = L.layerGroup().addTo(this.map);
    this.startLayer = L.layerGroup().addTo(this.map);
    this.overlayLayer = L.layerGroup().addTo(this.map);
    this.layersControl = L.control.layers(this.baseLayers, {
      Ramp: this.rampLayer,
      Obstacles: this.obstacleLayer,
      'Planned path': this.planLayer,
      'Smoothed path': this.smoothedLayer,
      'Real track': this.trackLayer,
      Boat: this.boatLayer,
    }, { collapsed: true, position: 'topright' }).addTo(this.map);

    this.boatMarker = null;
    this.plannedGhost = null;
    this.obstacles = [];
    this.trackLatLngs = [];
    this.map.on('click', (e) => {
      const [x, y] = this.frame.toRamp(e.latlng.lat, e.latlng.lng);
      this.handlers.onClick?.(x, y, e.latlng);
    });
    this.map.setView([0, 0], 18);
  }

  ll(x, y) {
    const [lat, lon] = this.frame.toLatLon(x, y);
    return L.latLng(lat, lon);
  }

  /** Container pixel of a ramp-frame point (for tests and overlays). */
  rampToContainerPoint(x, y) {
    const p = this.map.latLngToContainerPoint(this.ll(x, y));
    return { x: p.x, y: p.y };
  }

  setOrigin(origin) {
    const o = origin ?? { lat: 0, lon: 0, ramp_bearing_deg: 90 };
    const changed = !this.hasOrigin !== !origin || this.frame.lat !== o.lat
      || this.frame.lon !== o.lon || this.frame.rampBearingDeg !== o.ramp_bearing_deg;
    this.hasOrigin = Boolean(origin);
    if (!changed) return false;
    this.frame = new RampFrame(o.lat, o.lon, o.ramp_bearing_deg);
    this.drawRamp();
    this.grid.redraw();
    return true;
  }

  setTileUrl(url) {
    if (this.tiles) {
      this.layersControl.removeLayer(this.tiles);
      this.map.removeLayer(this.tiles);
      this.tiles = null;
    }
    if (!url) {
      this.grid.addTo(this.map);
      return;
    }
    let host = url;
    try {
      host = new URL(url.replace(/[{}]/g, '')).host;
    } catch {
      // keep the raw text as the attribution
    }
    const tiles = L.tileLayer(url, { maxZoom: 24, maxNativeZoom: 19,
      attribution: `map tiles: ${host}` });
    this.tiles = L.layerGroup([tiles, new RampGrid(() => this.frame)]);
    this.layersControl.addBaseLayer(this.tiles, `Online map (${host}) + grid`);
    this.map.removeLayer(this.grid);
    this.tiles.addTo(this.map);
  }

  /** An offline chart package from the station (GET /api/charts), or null for none. */
  setChart(pkg) {
    if (this.chart) {
      this.layersControl.removeLayer(this.chart);
      this.map.removeLayer(this.chart);
      this.chart = null;
    }
    if (!pkg) return;
    const opts = { maxZoom: 24, className: 'chart-tiles',
      attribution: pkg.attribution ?? `chart: ${pkg.title}` };
    if (pkg.maxzoom != null) opts.maxNativeZoom = pkg.maxzoom;
    if (pkg.minzoom != null) opts.minNativeZoom = pkg.minzoom;
    if (pkg.bounds) {
      const [w, south, e, n] = pkg.bounds;
      opts.bounds = L.latLngBounds([south, w], [n, e]);
    }
    this.chart = L.tileLayer(pkg.tiles, opts);
    this.layersControl.addOverlay(this.chart, `Offline chart: ${pkg.title}`);
    this.chart.addTo(this.map);
  }

  /** The shown run's boat at the displayed time (replay), or none. */
  setReplayBoat(row) {
    if (!row || row.lat == null) {
      if (this.replayMarker) {
        this.replayMarker.remove();
        this.replayMarker = null;
      }
      return;
    }
    const ll = L.latLng(row.lat, row.lon);
    if (!this.replayMarker) {
      this.replayMarker = L.marker(ll, { icon: replayIcon(), keyboard: false, interactive: false,
        zIndexOffset: 900 }).addTo(this.boatLayer);
    } else {
      this.replayMarker.setLatLng(ll);
    }
    const glyph = this.replayMarker.getElement()?.querySelector('.boat-glyph');
    if (glyph) glyph.style.transform = `rotate(${row.heading_deg}deg)`;
  }

  /** Pan to the boat's last position, if there is one. */
  centreOnBoat() {
    if (this.boatMarker) this.map.panTo(this.boatMarker.getLatLng());
  }

  drawRamp(axisLength = 150) {
    this.rampLayer.clearLayers();
    const h = RAMP_WIDTH_M / 2;
    const corners = [[-RAMP_LENGTH_M, -h], [0, -h], [0, h], [-RAMP_LENGTH_M, h]];
    L.polygon(corners.map(([x, y]) => this.ll(x, y)), { color: '#4a5568', fillColor: '#718096',
      fillOpacity: 0.8, weight: 1, interactive: false, className: 'ramp' })
      .addTo(this.rampLayer);
    L.polyline([this.ll(0, 0), this.ll(axisLength, 0)], { color: '#2d3748', weight: 1.5,
      dashArray: '8 6', interactive: false, className: 'ramp-axis' }).addTo(this.rampLayer);
    L.marker(this.ll(-RAMP_LENGTH_M / 2, 0), { interactive: false, keyboard: false,
      icon: L.divIcon({ className: 'map-label', html: 'ramp', iconSize: [40, 14],
        iconAnchor: [20, -6] }) }).addTo(this.rampLayer);
  }

  fitScenario(scenario) {
    const pts = [[0, 0], [-RAMP_LENGTH_M, 0], [scenario.start.x, scenario.start.y]];
    for (const o of scenario.obstacles) {
      pts.push([o.x - o.radius, o.y - o.radius], [o.x + o.radius, o.y + o.radius]);
    }
    this.map.fitBounds(L.latLngBounds(pts.map(([x, y]) => this.ll(x, y))), { padding: [30, 30] });
  }

  /** Obstacles (real and inflated circles, moving ones with their track) and the start. */
  setScenario(scenario, { editable = true } = {}) {
    this.scenario = scenario;
    const reach = Math.max(scenario.start.x, ...scenario.obstacles.map((o) => o.x + o.radius), 60);
    this.drawRamp(reach + 20);
    this.obstacleLayer.clearLayers();
    this.obstacles = scenario.obstacles.map((o, i) => this.drawObstacle(scenario, o, i, editable));
    this.startLayer.clearLayers();
    const s = scenario.start;
    const marker = L.marker(this.ll(s.x, s.y), {
      draggable: editable,
      keyboard: false,
      title: `start x ${fmtM(s.x)} m, y ${fmtM(s.y)} m`,
      icon: handleIcon('S', 'start-handle'),
    }).addTo(this.startLayer);
    marker.on('dragend', () => {
      const p = marker.getLatLng();
      this.handlers.onStartMoved?.(...this.frame.toRamp(p.lat, p.lng));
    });
    this.setDisplayTime(this.displayT);
  }

  drawObstacle(scenario, o, i, editable) {
    const moving = o.vx !== 0 || o.vy !== 0;
    const inflated = inflatedRadius(scenario, o);
    const body = L.circle(this.ll(o.x, o.y), { radius: o.radius, color: '#7b341e',
      fillColor: moving ? '#dd6b20' : '#9c4221', fillOpacity: 0.65, weight: 1,
      className: 'obstacle', interactive: false });
    const halo = L.circle(this.ll(o.x, o.y), { radius: inflated, color: '#9c4221', weight: 1,
      dashArray: '4 4', fill: false, interactive: false, className: 'obstacle-inflated' });
    const layers = [halo, body];
    if (moving) {
      const end = [o.x + o.vx * this.horizon, o.y + o.vy * this.horizon];
      layers.push(L.polyline([this.ll(o.x, o.y), this.ll(...end)], { color: '#dd6b20', weight: 1.5,
        dashArray: '2 6', interactive: false, className: 'obstacle-track' }));
    }
    const handle = L.marker(this.ll(o.x, o.y), {
      draggable: editable,
      keyboard: false,
      title: `obstacle ${i + 1}: x ${fmtM(o.x)} m, y ${fmtM(o.y)} m, radius ${o.radius} m`
        + (moving ? `, velocity (${o.vx}, ${o.vy}) m/s` : ''),
      icon: handleIcon(String(i + 1), 'obstacle-handle'),
    });
    handle.on('dragend', () => {
      const p = handle.getLatLng();
      this.handlers.onObstacleMoved?.(i, ...this.frame.toRamp(p.lat, p.lng));
    });
    layers.push(handle);
    for (const layer of layers) layer.addTo(this.obstacleLayer);
    return { o, body, halo, moving };
  }

  setHorizon(seconds) {
    this.horizon = Math.max(seconds, 1);
  }

  /** Moving obstacles and the planned position at displayed time t (s after the plan start). */
  setDisplayTime(t) {
    this.displayT = t;
    for (const { o, body, halo, moving } of this.obstacles) {
      if (!moving) continue;
      const c = this.ll(o.x + o.vx * t, o.y + o.vy * t);
      body.setLatLng(c);
      halo.setLatLng(c);
    }
    if (this.plan) {
      const p = planPositionAt(this.plan.waypoints, t);
      if (!this.plannedGhost) {
        this.plannedGhost = L.circleMarker(this.ll(p.x, p.y), { radius: 7, color: '#2b6cb0',
          weight: 2, fillOpacity: 0.15, interactive: false, className: 'planned-position' })
          .addTo(this.planLayer);
      } else {
        this.plannedGhost.setLatLng(this.ll(p.x, p.y));
      }
    }
  }

  /** The planned path coloured by speed, its waypoints and the smoothed path. */
  setPlan(plan, vessel) {
    this.plan = plan;
    this.planLayer.clearLayers();
    this.smoothedLayer.clearLayers();
    this.plannedGhost = null;
    if (!plan) return;
    const wps = plan.waypoints;
    const vmin = vessel?.speed_min ?? Math.min(...wps.map((w) => w.speed));
    const vmax = vessel?.speed_max ?? Math.max(...wps.map((w) => w.speed));
    this.speedRange = [vmin, vmax];
    for (let i = 1; i < wps.length; i++) {
      const a = wps[i - 1];
      const b = wps[i];
      const v = (a.speed + b.speed) / 2;
      L.polyline([this.ll(a.x, a.y), this.ll(b.x, b.y)], { color: speedColour(v, vmin, vmax),
        weight: 5, opacity: 0.95, className: 'plan-segment' })
        .bindTooltip(`leg ${i}: ${v.toFixed(2)} m/s, ${(b.t - a.t).toFixed(1)} s`, { sticky: true })
        .addTo(this.planLayer);
    }
    wps.forEach((w, i) => {
      L.circleMarker(this.ll(w.x, w.y), { radius: 3.5, color: '#1a202c', weight: 1,
        fillColor: '#fff', fillOpacity: 1, className: 'plan-waypoint' })
        .bindTooltip(`waypoint ${i}: x ${fmtM(w.x)} m, y ${fmtM(w.y)} m, t ${w.t.toFixed(1)} s, `
          + `${w.speed.toFixed(2)} m/s, heading ${w.heading_deg.toFixed(1)}°`)
        .addTo(this.planLayer);
    });
    const smooth = plan.smoothed?.points;
    if (smooth && smooth.length > 1) {
      L.polyline(smooth.map((p) => this.ll(p.x, p.y)), { color: '#1a365d', weight: 1.5,
        dashArray: '5 4', interactive: false, className: 'smoothed-path' })
        .addTo(this.smoothedLayer);
    }
    this.setDisplayTime(this.displayT);
  }

  /** A second plan to compare with, dashed, or none. */
  setOverlayPlan(plan) {
    this.overlayLayer.clearLayers();
    if (!plan) return;
    L.polyline(plan.waypoints.map((w) => this.ll(w.x, w.y)), { color: '#553c9a', weight: 3,
      dashArray: '10 6', className: 'overlay-plan' })
      .bindTooltip(`${plan.planner} plan, seed ${plan.seed}`, { sticky: true })
      .addTo(this.overlayLayer);
  }

  /** Replace the real track with telemetry rows (lat/lon from the boat's GPS). */
  setTrack(rows) {
    this.trackLatLngs = rows.filter((r) => r.lat != null).map((r) => L.latLng(r.lat, r.lon));
    this.trackLine.setLatLngs(this.trackLatLngs);
  }

  appendTrack(rows) {
    for (const r of rows) if (r.lat != null) this.trackLatLngs.push(L.latLng(r.lat, r.lon));
    this.trackLine.setLatLngs(this.trackLatLngs);
  }

  /** The boat's live position and compass heading. */
  setBoat(row) {
    if (!row || row.lat == null) return;
    const ll = L.latLng(row.lat, row.lon);
    if (!this.boatMarker) {
      this.boatMarker = L.marker(ll, { icon: boatIcon(), keyboard: false, interactive: false,
        zIndexOffset: 1000 }).addTo(this.boatLayer);
    } else {
      this.boatMarker.setLatLng(ll);
    }
    const glyph = this.boatMarker.getElement()?.querySelector('.boat-glyph');
    if (glyph) glyph.style.transform = `rotate(${row.heading_deg}deg)`;
  }

  centreRamp() {
    const c = this.map.getCenter();
    return this.frame.toRamp(c.lat, c.lng);
  }

  invalidateSize() {
    this.map.invalidateSize();
  }
}
