"""The FastAPI application: routes, websocket, auth."""
