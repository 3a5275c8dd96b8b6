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

const BOAT_PATH = 'M0,-12 L7,9 L0,5 L-7,9 Z';

function glyphIcon(className, svgBody, size = 28) {
  const h = size / 2;
  return L.divIcon({
    className,
    iconSize: [size, size],
    iconAnchor: [h, h],
    html: `<svg class="boat-glyph" viewBox="${-h} ${-h} ${size} ${size}" width="${size}" `
      + `height="${size}" aria-hidden="true">${svgBody}</svg>`,
  });
}

function boatIcon() {
  return glyphIcon('boat-marker',
    `<path d="${BOAT_PATH}" fill="#c53030" stroke="#fff" stroke-width="1.5"/>`);
}

function replayIcon() {
  return glyphIcon('replay-boat',
    `<path d="${BOAT_PATH}" fill="none" stroke="#c53030" stroke-width="2"/>`);
}

function handleIcon(label, cls) {
  return L.divIcon({ className: `map-handle ${cls}`, iconSize: [22, 22], iconAnchor: [11, 11],
    html: `<span>${label}</span>` });
}

/** The SVG of a target's symbol by source (OpenCPN's conventions): AIS class A a triangle,
 * class B a smaller one, ARPA (radar) a circle, a manual (planned) obstacle a diamond; lost
 * targets crossed out. Pointing up: turned by the caller to its heading or course. */
export function targetGlyph(target) {
  let body;
  if (target.source === 'ais') {
    body = target.ais_class === 'B' ? '<path class="hull" d="M0,-9 L5,7 L-5,7 Z"/>'
      : '<path class="hull" d="M0,-12 L7,9 L-7,9 Z"/>';
  } else if (target.source === 'arpa') {
    body = '<circle class="hull" r="7"/><path class="hull" d="M0,-7 L0,-12"/>';
  } else {
    body = '<path class="hull" d="M0,-9 L8,0 L0,9 L-8,0 Z"/>';
  }
  if (target.lost) body += '<path class="lost-cross" d="M-10,-10 L10,10 M10,-10 L-10,10"/>';
  return body;
}

/** The name a target is shown by: its name, else its MMSI, else its id. */
export function targetName(t) {
  return t.name || (t.mmsi ? String(t.mmsi) : t.id);
}

const KIND = { ais: 'AIS', arpa: 'ARPA', manual: 'manual', sim: 'simulated' };

export function targetClass(t) {
  return t.source === 'ais' ? `AIS ${t.ais_class ?? ''}`.trim() : KIND[t.source] ?? t.source;
}

/** A CRS for the ship-up view: the tangent plane of `frame` in metres, turned so that the
 * ramp frame's -x (from the sea towards the ramp: the bow of a stern-ramp ship) points up
 * the screen; zoom levels match Web Mercator's at the frame's latitude. Circles keep their
 * radius in metres (Leaflet's non-Earth branch). */
function shipUpCrs(frame) {
  const k = 1 / Math.cos((frame.lat * Math.PI) / 180);
  const a = (0.5 / (Math.PI * L.Projection.SphericalMercator.R)) * k;
  const projection = {
    project(latlng) {
      const ll = L.latLng(latlng);
      const [x, y] = frame.toRamp(ll.lat, ll.lng);
      return L.point(y, -x);
    },
    unproject(point) {
      const [lat, lon] = frame.toLatLon(-point.y, point.x);
      return L.latLng(lat, lon);
    },
    bounds: L.bounds([-1e7, -1e7], [1e7, 1e7]),
  };
  return L.Util.extend({}, L.CRS, {
    code: 'USV:ship-up',
    projection,
    transformation: L.transformation(a, 0.5, -a, 0.5),
    infinite: true,
    distance: (p, q) => L.CRS.Earth.distance(p, q),
  });
}

function sameFrame(a, b) {
  return Boolean(a) && Boolean(b) && Math.abs(a.lat - b.lat) < 1e-9
    && Math.abs(a.lon - b.lon) < 1e-9 && Math.abs(a.rampBearingDeg - b.rampBearingDeg) < 1e-6;
}

/** The ramp frame where a telemetry row puts it: the boat's lat/lon less its ramp-frame x, y
 * (the ship's bearing taken as `bearingDeg`); null without a ramp-frame position. */
export function frameOfRow(row, bearingDeg) {
  if (!row || row.x == null || row.lat == null) return null;
  const [lat, lon] = new RampFrame(row.lat, row.lon, bearingDeg).toLatLon(-row.x, -row.y);
  return new RampFrame(lat, lon, bearingDeg);
}

export class ConsoleMap {
  /**
   * @param {HTMLElement} el
   * @param {{onClick(x, y), onStartMoved(x, y), onObstacleMoved(i, x, y)}} handlers
   */
  constructor(el, handlers) {
    this.handlers = handlers;
    // The ramp frame everything is drawn in: the replayed run's (where the ship was), else
    // the live one (the own ship's, moving), else the scenario's fixed origin.
    this.originFrame = new RampFrame(0, 0, 90);
    this.liveFrame = null;
    this.replayFrame = null;
    this.rampStale = false;
    this.hasOrigin = false;
    this.horizon = 120;
    this.displayT = 0;
    this.orientation = 'north';
    this.keepShip = true;
    this.items = []; // ramp-frame drawings, re-placed whenever the frame moves
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

    this.shipLayer = L.layerGroup().addTo(this.map);
    this.rampLayer = L.layerGroup().addTo(this.map);
    this.obstacleLayer = L.layerGroup().addTo(this.map);
    this.targetLayer = L.layerGroup().addTo(this.map);
    this.planLayer = L.layerGroup().addTo(this.map);
    this.proposedLayer = L.layerGroup().addTo(this.map);
    this.smoothedLayer = L.layerGroup().addTo(this.map);
    this.trackLine = L.polyline([], { color: '#c53030', weight: 3, className: 'real-track',
      interactive: false });
    this.trackLayer = L.layerGroup([this.trackLine]).addTo(this.map);
    this.boatLayer = L.layerGroup().addTo(this.map);
    this.startLayer = L.layerGroup().addTo(this.map);
    this.overlayLayer = L.layerGroup().addTo(this.map);
    this.layersControl = L.control.layers(this.baseLayers, {
      'Mother ship': this.shipLayer,
      Ramp: this.rampLayer,
      Obstacles: this.obstacleLayer,
      Targets: this.targetLayer,
      'Planned path': this.planLayer,
      'Proposed re-plan': this.proposedLayer,
      'Smoothed path': this.smoothedLayer,
      'Real track': this.trackLayer,
      Boat: this.boatLayer,
    }, { collapsed: true, position: 'topright' }).addTo(this.map);

    this.boatMarker = null;
    this.boatRow = null;
    this.plannedGhost = null;
    this.obstacles = [];
    this.trackRows = [];
    this.trackLatLngs = [];
    this.targets = new Map(); // id -> {marker, vector, target}
    this.targetOptions = { minutes: 3, danger: new Set(), flash: new Set() };
    this.map.on('click', (e) => {
      const [x, y] = this.frame.toRamp(e.latlng.lat, e.latlng.lng);
      this.handlers.onClick?.(x, y, e.latlng);
    });
    this.map.setView([0, 0], 18);
  }

  get frame() {
    return this.replayFrame ?? this.liveFrame ?? this.originFrame;
  }

  /** Compass bearing of the screen's up direction (0 north up; ship up: the ramp's -x). */
  get screenUpDeg() {
    return this.orientation === 'ship' ? (this.frame.rampBearingDeg + 180) % 360 : 0;
  }

  ll(x, y) {
    const [lat, lon] = this.frame.toLatLon(x, y);
    return L.latLng(lat, lon);
  }

  // --- ramp-frame drawings: kept with their ramp coordinates, re-placed when the frame moves
  track(layer, group, ramp) {
    const item = { layer, group, ...ramp };
    layer.rampItem = item;
    this.items.push(item);
    layer.addTo(group);
    return layer;
  }

  rampPath(group, pts, options, polygon = false) {
    const make = polygon ? L.polygon : L.polyline;
    return this.track(make(pts.map(([x, y]) => this.ll(x, y)), options), group, { pts });
  }

  rampPoint(group, layer, x, y) {
    layer.setLatLng(this.ll(x, y));
    return this.track(layer, group, { xy: [x, y] });
  }

  moveRamp(layer, x, y) {
    if (layer.rampItem) layer.rampItem.xy = [x, y];
    layer.setLatLng(this.ll(x, y));
  }

  /** Re-place every ramp-frame drawing in the present frame. */
  reproject() {
    this.items = this.items.filter((it) => it.group.hasLayer(it.layer));
    for (const it of this.items) {
      if (it.pts) it.layer.setLatLngs(it.pts.map(([x, y]) => this.ll(x, y)));
      else it.layer.setLatLng(this.ll(...it.xy));
    }
    this.trackLatLngs = this.trackRows.map((r) => this.rowLatLng(r)).filter(Boolean);
    this.trackLine.setLatLngs(this.trackLatLngs);
    this.placeBoat();
    this.drawTargets();
    this.grid.redraw();
  }

  /** Move to `frame` (null: back to the next one down), keeping the view on the ship. */
  useFrame(kind, frame) {
    const before = this.frame;
    const centre = this.map.getCenter();
    const [cx, cy] = before.toRamp(centre.lat, centre.lng);
    this[kind] = frame;
    const after = this.frame;
    if (sameFrame(before, after)) return;
    if (this.orientation === 'ship' && Math.abs(before.rampBearingDeg - after.rampBearingDeg)
        > 0.5) {
      this.map.options.crs = shipUpCrs(after);
    }
    this.reproject();
    if (this.keepShip || this.orientation === 'ship') {
      this.map.setView(this.ll(cx, cy), this.map.getZoom(), { animate: false, reset: true });
    }
  }

  /** The ramp's pose from the world (`GET /api/world` `ramp`): from the own ship, the frame
   * moves with it; stale ones are marked; the fixed origin leaves the scenario's frame. */
  setRampPose(ramp) {
    const live = ramp && ramp.source === 'own_ship'
      ? new RampFrame(ramp.lat, ramp.lon, ramp.ramp_bearing_deg) : null;
    const stale = Boolean(live && ramp.stale);
    if (stale !== this.rampStale) {
      this.rampStale = stale;
      this.drawRamp(this.axisLength);
    }
    this.useFrame('liveFrame', live);
  }

  /** The replayed run's frame: where a stored row puts the ramp (null: back to live). */
  setReplayFrame(frame) {
    this.useFrame('replayFrame', frame);
  }

  /** Container pixel of a ramp-frame point (for tests and overlays). */
  rampToContainerPoint(x, y) {
    const p = this.map.latLngToContainerPoint(this.ll(x, y));
    return { x: p.x, y: p.y };
  }

  setOrigin(origin) {
    const o = origin ?? { lat: 0, lon: 0, ramp_bearing_deg: 90 };
    const f = this.originFrame;
    const changed = !this.hasOrigin !== !origin || f.lat !== o.lat
      || f.lon !== o.lon || f.rampBearingDeg !== o.ramp_bearing_deg;
    this.hasOrigin = Boolean(origin);
    if (!changed) return false;
    this.originFrame = new RampFrame(o.lat, o.lon, o.ramp_bearing_deg);
    this.reproject();
    return true;
  }

  /** North up (a chart, Web Mercator, tiles) or ship up (the ramp axis fixed on screen, the
   * ramp-frame grid only: tiles are north up). */
  setOrientation(mode) {
    if (mode === this.orientation) return;
    const centre = this.map.getCenter();
    const [cx, cy] = this.frame.toRamp(centre.lat, centre.lng);
    this.orientation = mode;
    const tiles = [this.tiles, this.chart].filter(Boolean);
    if (mode === 'ship') {
      for (const t of tiles) this.map.removeLayer(t);
      this.map.options.crs = shipUpCrs(this.frame);
    } else {
      this.map.options.crs = L.CRS.EPSG3857;
      for (const t of tiles) t.addTo(this.map);
    }
    this.map.getContainer().classList.toggle('ship-up', mode === 'ship');
    this.map.setView(this.ll(cx, cy), this.map.getZoom(), { animate: false, reset: true });
    this.reproject();
  }

  setKeepShip(keep) {
    this.keepShip = keep;
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
    if (this.orientation === 'north') this.tiles.addTo(this.map);
    else this.grid.addTo(this.map);
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
    if (this.orientation === 'north') this.chart.addTo(this.map);
  }

  /** Where a telemetry row is drawn: its ramp-frame x, y in the present frame (the plan's
   * frame), else its lat/lon. */
  rowLatLng(row) {
    if (!row) return null;
    if (row.x != null && row.y != null) return this.ll(row.x, row.y);
    return row.lat != null ? L.latLng(row.lat, row.lon) : null;
  }

  turn(marker, compassDeg) {
    const glyph = marker.getElement()?.querySelector('.boat-glyph');
    if (glyph && compassDeg != null) {
      glyph.style.transform = `rotate(${compassDeg - this.screenUpDeg}deg)`;
    }
  }

  /** The shown run's boat at the displayed time (replay), or none; the ship where it was. */
  setReplayBoat(row, bearingDeg = null) {
    if (!row || (row.lat == null && row.x == null)) {
      if (this.replayMarker) {
        this.replayMarker.remove();
        this.replayMarker = null;
      }
      this.setReplayFrame(null);
      return;
    }
    const bearing = bearingDeg ?? (this.liveFrame ?? this.originFrame).rampBearingDeg;
    this.setReplayFrame(frameOfRow(row, bearing));
    const ll = this.rowLatLng(row);
    if (!this.replayMarker) {
      this.replayMarker = L.marker(ll, { icon: replayIcon(), keyboard: false, interactive: false,
        zIndexOffset: 900 }).addTo(this.boatLayer);
    } else {
      this.replayMarker.setLatLng(ll);
    }
    this.turn(this.replayMarker, row.heading_deg);
  }

  /** Pan to the boat's last position, if there is one. */
  centreOnBoat() {
    if (this.boatMarker) this.map.panTo(this.boatMarker.getLatLng());
  }

  /** The ramp: the opening at the ramp end (the ship's ramp width), its axis out to sea;
   * dashed and labelled when the own ship's fix is stale (the pose is dead-reckoned). */
  drawRamp(axisLength = 150) {
    this.axisLength = axisLength;
    this.rampLayer.clearLayers();
    const h = (this.ship?.ramp_width ?? RAMP_WIDTH_M) / 2;
    const corners = [[-RAMP_LENGTH_M, -h], [0, -h], [0, h], [-RAMP_LENGTH_M, h]];
    const stale = this.rampStale ? ' stale' : '';
    this.rampPath(this.rampLayer, corners, { color: '#4a5568', fillColor: '#718096',
      fillOpacity: 0.8, weight: 1, interactive: false, className: `ramp${stale}`,
      dashArray: stale ? '4 3' : null }, true);
    this.rampPath(this.rampLayer, [[0, 0], [axisLength, 0]], { color: '#2d3748', weight: 1.5,
      dashArray: '8 6', interactive: false, className: 'ramp-axis' });
    const label = this.rampStale ? 'ramp (dead-reckoned: own ship stale)' : 'ramp';
    this.rampPoint(this.rampLayer, L.marker([0, 0], { interactive: false, keyboard: false,
      icon: L.divIcon({ className: `map-label${stale}`, html: label, iconSize: [40, 14],
        iconAnchor: [20, -6] }) }), -RAMP_LENGTH_M / 2, 0);
  }

  /** The mother ship (`GET /api/world` `ship`): its hull outline in the ramp frame, else its
   * length on the axis, and its position reference (the GNSS antenna of the lever arm). */
  setShip(ship) {
    const key = JSON.stringify(ship ?? null);
    if (key === this.shipKey) return;
    this.shipKey = key;
    this.ship = ship ?? null;
    this.shipLayer.clearLayers();
    this.drawRamp(this.axisLength);
    if (!ship) return;
    if (ship.outline) {
      this.rampPath(this.shipLayer, ship.outline, { color: '#2d3748', weight: 2,
        fillColor: '#a0aec0', fillOpacity: 0.35, interactive: true, className: 'ship-hull' }, true)
        .bindTooltip(`mother ship: ${ship.length} m${ship.beam ? ` x ${ship.beam} m` : ''}`,
          { sticky: true });
    } else {
      this.rampPath(this.shipLayer, [[0, 0], [-ship.length, 0]], { color: '#2d3748', weight: 6,
        opacity: 0.5, className: 'ship-hull ship-length' })
        .bindTooltip(`mother ship: ${ship.length} m (no beam or outline given)`,
          { sticky: true });
    }
    const [rx, ry] = ship.reference;
    this.rampPoint(this.shipLayer, L.marker([0, 0], { keyboard: false, title: 'own ship position reference (GNSS)',
      icon: L.divIcon({ className: 'ship-reference', iconSize: [14, 14], iconAnchor: [7, 7],
        html: '<svg viewBox="-7 -7 14 14" width="14" height="14" aria-hidden="true">'
          + '<path d="M-6,0 L6,0 M0,-6 L0,6" stroke="#1a202c" stroke-width="2"/></svg>' }) }),
    rx, ry);
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
    const marker = this.rampPoint(this.startLayer, L.marker([0, 0], {
      draggable: editable,
      keyboard: false,
      title: `start x ${fmtM(s.x)} m, y ${fmtM(s.y)} m`,
      icon: handleIcon('S', 'start-handle'),
    }), s.x, s.y);
    marker.on('dragend', () => {
      const p = marker.getLatLng();
      this.handlers.onStartMoved?.(...this.frame.toRamp(p.lat, p.lng));
    });
    this.setDisplayTime(this.displayT);
  }

  drawObstacle(scenario, o, i, editable) {
    const moving = o.vx !== 0 || o.vy !== 0;
    const inflated = inflatedRadius(scenario, o);
    const group = this.obstacleLayer;
    const halo = this.rampPoint(group, L.circle([0, 0], { radius: inflated, color: '#9c4221',
      weight: 1, dashArray: '4 4', fill: false, interactive: false,
      className: 'obstacle-inflated' }), o.x, o.y);
    const body = this.rampPoint(group, L.circle([0, 0], { radius: o.radius, color: '#7b341e',
      fillColor: moving ? '#dd6b20' : '#9c4221', fillOpacity: 0.65, weight: 1,
      className: 'obstacle', interactive: false }), o.x, o.y);
    if (moving) {
      const end = [o.x + o.vx * this.horizon, o.y + o.vy * this.horizon];
      this.rampPath(group, [[o.x, o.y], end], { color: '#dd6b20', weight: 1.5,
        dashArray: '2 6', interactive: false, className: 'obstacle-track' });
    }
    const handle = this.rampPoint(group, L.marker([0, 0], {
      draggable: editable,
      keyboard: false,
      title: `obstacle ${i + 1}: x ${fmtM(o.x)} m, y ${fmtM(o.y)} m, radius ${o.radius} m`
        + (moving ? `, velocity (${o.vx}, ${o.vy}) m/s` : ''),
      icon: handleIcon(String(i + 1), 'obstacle-handle'),
    }), o.x, o.y);
    handle.on('dragend', () => {
      const p = handle.getLatLng();
      this.handlers.onObstacleMoved?.(i, ...this.frame.toRamp(p.lat, p.lng));
    });
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
      this.moveRamp(body, o.x + o.vx * t, o.y + o.vy * t);
      this.moveRamp(halo, o.x + o.vx * t, o.y + o.vy * t);
    }
    if (this.plan) {
      const p = planPositionAt(this.plan.waypoints, t);
      if (!this.plannedGhost) {
        this.plannedGhost = this.rampPoint(this.planLayer, L.circleMarker([0, 0], { radius: 7,
          color: '#2b6cb0', weight: 2, fillOpacity: 0.15, interactive: false,
          className: 'planned-position' }), p.x, p.y);
      } else {
        this.moveRamp(this.plannedGhost, p.x, p.y);
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
      this.rampPath(this.planLayer, [[a.x, a.y], [b.x, b.y]], {
        color: speedColour(v, vmin, vmax), weight: 5, opacity: 0.95, className: 'plan-segment' })
        .bindTooltip(`leg ${i}: ${v.toFixed(2)} m/s, ${(b.t - a.t).toFixed(1)} s`, { sticky: true });
    }
    wps.forEach((w, i) => {
      this.rampPoint(this.planLayer, L.circleMarker([0, 0], { radius: 3.5, color: '#1a202c',
        weight: 1, fillColor: '#fff', fillOpacity: 1, className: 'plan-waypoint' }), w.x, w.y)
        .bindTooltip(`waypoint ${i}: x ${fmtM(w.x)} m, y ${fmtM(w.y)} m, t ${w.t.toFixed(1)} s, `
          + `${w.speed.toFixed(2)} m/s, heading ${w.heading_deg.toFixed(1)}°`);
    });
    const smooth = plan.smoothed?.points;
    if (smooth && smooth.length > 1) {
      this.rampPath(this.smoothedLayer, smooth.map((p) => [p.x, p.y]), { color: '#1a365d',
        weight: 1.5, dashArray: '5 4', interactive: false, className: 'smoothed-path' });
    }
    this.setDisplayTime(this.displayT);
  }

  /** A proposed re-plan beside the running plan (dashed, green), or none. */
  setProposedPlan(plan) {
    this.proposedLayer.clearLayers();
    if (!plan) return;
    this.rampPath(this.proposedLayer, plan.waypoints.map((w) => [w.x, w.y]), {
      color: '#2f855a', weight: 4, dashArray: '10 6', className: 'proposed-plan' })
      .bindTooltip('proposed re-plan', { sticky: true });
  }

  /** A second plan to compare with, dashed, or none. */
  setOverlayPlan(plan) {
    this.overlayLayer.clearLayers();
    if (!plan) return;
    this.rampPath(this.overlayLayer, plan.waypoints.map((w) => [w.x, w.y]), { color: '#553c9a',
      weight: 3, dashArray: '10 6', className: 'overlay-plan' })
      .bindTooltip(`${plan.planner} plan, seed ${plan.seed}`, { sticky: true });
  }

  /** Replace the real track with telemetry rows (drawn in the ramp frame, as the plan). */
  setTrack(rows) {
    this.trackRows = rows.filter((r) => r.lat != null || r.x != null);
    this.trackLatLngs = this.trackRows.map((r) => this.rowLatLng(r));
    this.trackLine.setLatLngs(this.trackLatLngs);
  }

  appendTrack(rows) {
    for (const r of rows) {
      const ll = this.rowLatLng(r);
      if (!ll) continue;
      this.trackRows.push(r);
      this.trackLatLngs.push(ll);
    }
    this.trackLine.setLatLngs(this.trackLatLngs);
  }

  /** The boat's live position (ramp-frame x, y in the present frame) and compass heading. */
  setBoat(row) {
    if (!row || (row.lat == null && row.x == null)) return;
    this.boatRow = row;
    this.placeBoat();
  }

  placeBoat() {
    const ll = this.rowLatLng(this.boatRow);
    if (!ll) return;
    if (!this.boatMarker) {
      this.boatMarker = L.marker(ll, { icon: boatIcon(), keyboard: false, interactive: false,
        zIndexOffset: 1000 }).addTo(this.boatLayer);
    } else {
      this.boatMarker.setLatLng(ll);
    }
    this.turn(this.boatMarker, this.boatRow.heading_deg);
  }

  /** The world's targets (`GET /api/world` `targets`, ramp frame of now) with their COG/SOG
   * vector of `minutes`; `danger` ids red, `flash` ids flashing (unacknowledged alerts). */
  setTargets(targets, options = {}) {
    this.targetOptions = { ...this.targetOptions, ...options };
    const seen = new Set();
    // the plan's own obstacles (manual tracks) are drawn from the scenario, not twice
    for (const t of targets.filter((g) => g.source !== 'manual')) {
      seen.add(t.id);
      let entry = this.targets.get(t.id);
      if (!entry) {
        const marker = L.marker([0, 0], { keyboard: false, riseOnHover: true,
          icon: L.divIcon({ className: 'target-marker', iconSize: [28, 28], iconAnchor: [14, 14],
            html: '' }) });
        const vector = L.polyline([], { weight: 2, interactive: false, className: 'target-vector' });
        const relative = L.polyline([], { weight: 1.5, dashArray: '3 4', interactive: false,
          className: 'target-relative' });
        const size = L.circle([0, 0], { radius: t.radius, weight: 1, dashArray: '2 3',
          fillOpacity: 0.08, interactive: false, className: 'target-size' });
        size.addTo(this.targetLayer);
        marker.addTo(this.targetLayer);
        vector.addTo(this.targetLayer);
        relative.addTo(this.targetLayer);
        marker.bindTooltip('', { direction: 'top', offset: [0, -12] });
        entry = { marker, vector, relative, size, target: t, html: null };
        this.targets.set(t.id, entry);
      }
      entry.target = t;
    }
    for (const [id, entry] of this.targets) {
      if (seen.has(id)) continue;
      for (const layer of [entry.marker, entry.vector, entry.relative, entry.size]) layer.remove();
      this.targets.delete(id);
    }
    this.drawTargets();
  }

  drawTargets() {
    if (!this.targets) return;
    const { minutes, danger, flash } = this.targetOptions;
    for (const entry of this.targets.values()) {
      const t = entry.target;
      const cls = ['target-marker', `source-${t.source}`, danger.has(t.id) ? 'danger' : '',
        t.lost ? 'lost' : '', flash.has(t.id) ? 'flash' : ''].filter(Boolean).join(' ');
      const html = `<svg class="boat-glyph" viewBox="-14 -14 28 28" width="28" height="28" `
        + `aria-hidden="true">${targetGlyph(t)}</svg>`;
      if (entry.html !== html || entry.cls !== cls) {
        entry.marker.setIcon(L.divIcon({ className: cls, iconSize: [28, 28], iconAnchor: [14, 14],
          html }));
        entry.html = html;
        entry.cls = cls;
      }
      entry.marker.setLatLng(this.ll(t.x, t.y));
      entry.marker.getElement()?.setAttribute('data-target', t.id);
      entry.size.setLatLng(this.ll(t.x, t.y));
      entry.size.setRadius(t.radius); // its hull to scale: half its length (5 m unknown)
      entry.size.getElement()?.classList.toggle('danger', danger.has(t.id));
      this.turn(entry.marker, t.heading_deg ?? t.course_deg);
      const secs = minutes * 60;
      // true (over ground, solid) and relative to the ship (dashed: where the plan sees it)
      entry.vector.setLatLngs(t.speed > 0.05 && !t.lost
        ? [this.ll(t.x, t.y), this.ll(t.x + t.vx * secs, t.y + t.vy * secs)] : []);
      entry.relative.setLatLngs(Math.hypot(t.rvx, t.rvy) > 0.05 && !t.lost
        ? [this.ll(t.x, t.y), this.ll(t.x + t.rvx * secs, t.y + t.rvy * secs)] : []);
      entry.vector.getElement()?.classList.toggle('danger', danger.has(t.id));
      entry.marker.setTooltipContent(`${targetName(t)}${t.mmsi && t.name ? ` (MMSI ${t.mmsi})`
        : ''}: ${targetClass(t)}, SOG ${t.speed.toFixed(1)} m/s, COG ${t.course_deg.toFixed(0)}°`
        + `${t.lost ? ', lost' : ''}`);
    }
  }

  centreRamp() {
    const c = this.map.getCenter();
    return this.frame.toRamp(c.lat, c.lng);
  }

  invalidateSize() {
    this.map.invalidateSize();
  }
}
