# Shore station image: `docker build -t usv-station .` then see README "Docker".
# Stage 1 builds wheels for the package and its dependencies; stage 2 installs them into a
# slim runtime that runs as a non-root user with the data directory on a volume.
FROM python:3.11-slim AS build
WORKDIR /src
COPY pyproject.toml README.md ./
COPY backend ./backend
RUN pip wheel --no-cache-dir --wheel-dir /wheels .

FROM python:3.11-slim
RUN useradd --create-home --uid 10001 --groups dialout station \
    && mkdir /data && chown station:station /data
COPY --from=build /wheels /wheels
RUN pip install --no-cache-dir /wheels/*.whl && rm -rf /wheels
USER station
WORKDIR /home/station
ENV USV_STATION_DATA_DIR=/data \
    USV_STATION_HOST=0.0.0.0 \
    PYTHONUNBUFFERED=1
VOLUME ["/data"]
EXPOSE 8000 8080
HEALTHCHECK --interval=30s --timeout=5s CMD python -c "import urllib.request,sys; urllib.request.urlopen('http://127.0.0.1:8000/api/health', timeout=4); sys.exit(0)"
ENTRYPOINT ["usv-station", "serve"]
