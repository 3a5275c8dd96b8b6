# Shore station image: `docker build -t usv-station .` then see README "Docker".
# Stage 1 builds wheels for the package and its dependencies; stage 2 installs the
# console's npm packages (Leaflet, uPlot); stage 3 is a slim runtime that runs as a
# non-root user with the data directory on a volume.
FROM python:3.11-slim AS build
WORKDIR /src
COPY pyproject.toml README.md ./
COPY backend ./backend
RUN pip wheel --no-cache-dir --wheel-dir /wheels .

FROM node:20-slim AS console
WORKDIR /frontend
COPY frontend/package.json frontend/package-lock.json ./
RUN npm ci --no-audit --no-fund --omit=dev --loglevel=error
COPY frontend/index.html ./
COPY frontend/app ./app

FROM python:3.11-slim
RUN useradd --create-home --uid 10001 --groups dialout station \
    && mkdir /data && chown station:station /data
COPY --from=build /wheels /wheels
RUN pip install --no-cache-dir /wheels/*.whl && rm -rf /wheels
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
EXPOSE 8000 8080
HEALTHCHECK --interval=30s --timeout=5s CMD python -c "import urllib.request,sys; urllib.request.urlopen('http://127.0.0.1:8000/api/health', timeout=4); sys.exit(0)"
ENTRYPOINT ["usv-station", "serve"]
