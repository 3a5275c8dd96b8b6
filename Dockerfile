# Shore station image: `docker build -t usv-station .` then see README "Docker".
# Stage 1 builds wheels for the package and its dependencies; stage 2 installs the
# console's npm packages (Leaflet, uPlot); stage 3 is a slim runtime that runs as a
# non-root user with the data directory on a volume.
#
# Base images are pinned by digest (the tag beside it is for the reader; Docker pulls the
# digest): python:3.11-slim is Python 3.11.16 on Debian trixie (multi-arch index),
# node:20-slim is Node 20.20.2 on Debian bookworm. To move to newer ones:
#   docker buildx imagetools inspect python:3.11-slim   (and node:20-slim)
# and replace both digests here.
FROM python:3.11-slim@sha256:9c900dea9e8fb7e16277c179b555cc72d29a352dbc33cff48ad5a0412fd5bfc7 AS build
WORKDIR /src
COPY pyproject.toml README.md ./
COPY backend ./backend
RUN pip wheel --no-cache-dir --wheel-dir /wheels .

FROM node:20-slim@sha256:1e85773c98c31d4fe5b545e4cb17379e617b348832fb3738b22a08f68dec30f3 AS console
WORKDIR /frontend
COPY frontend/package.json frontend/package-lock.json ./
RUN npm ci --no-audit --no-fund --omit=dev --loglevel=error
COPY frontend/index.html ./
COPY frontend/app ./app

FROM python:3.11-slim@sha256:9c900dea9e8fb7e16277c179b555cc72d29a352dbc33cff48ad5a0412fd5bfc7
RUN useradd --create-home --uid 10001 --groups dialout station \
    && mkdir /data && chown station:station /data
COPY --from=build /wheels /wheels
RUN pip install --no-cache-dir /wheels/*.whl && rm -rf /wheels \
    && python -c "from usvstation.planning.warm import warm; warm()"
# (the IGA's numba kernels compiled into their cache beside the package, once, at build)
# the console keeps its layout: index.html, app/, node_modules/<pkg>/dist
COPY --from=console /frontend/index.html /opt/usv-station/frontend/index.html
COPY --from=console /frontend/app /opt/usv-station/frontend/app
COPY --from=console /frontend/node_modules/leaflet/dist /opt/usv-station/frontend/node_modules/leaflet/dist
COPY --from=console /frontend/node_modules/uplot/dist /opt/usv-station/frontend/node_modules/uplot/dist
# /docs and /redoc from the station itself (no CDN on a ship)
COPY --from=console /frontend/node_modules/swagger-ui-dist /opt/usv-station/frontend/node_modules/swagger-ui-dist
COPY --from=console /frontend/node_modules/redoc/bundles /opt/usv-station/frontend/node_modules/redoc/bundles
USER station
WORKDIR /home/station
ENV USV_STATION_DATA_DIR=/data \
    USV_STATION_HOST=0.0.0.0 \
    USV_STATION_FRONTEND_DIR=/opt/usv-station/frontend \
    PYTHONUNBUFFERED=1
VOLUME ["/data"]
# only the station's port: the 3D view is reached through it (/3d/), its own port stays
# on the container's loopback
EXPOSE 8000
# unhealthy unless /api/health says "ok" (a "degraded" station, e.g. its telemetry writer
# failing or no plan worker alive, fails it too)
HEALTHCHECK --interval=30s --timeout=5s --start-period=30s --retries=3 CMD ["python", "-c", "import json, os, sys, urllib.request; port = os.environ.get('USV_STATION_PORT', '8000'); health = json.load(urllib.request.urlopen(f'http://127.0.0.1:{port}/api/health', timeout=4)); sys.exit(0 if health.get('status') == 'ok' else 1)"]
ENTRYPOINT ["usv-station", "serve"]
