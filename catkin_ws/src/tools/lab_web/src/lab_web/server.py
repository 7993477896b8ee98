"""The web server (aiohttp): the page at /, its files under /static/, and one WebSocket per open page at /ws.

No ROS import: it talks to a bridge (lab_web.ros_bridge.RosBridge, or any object with the same methods). Each
page gets at most UPDATES_PER_S frames of state per second, only what changed since its last frame, and a slow
page simply gets fewer (each send waits for the previous one). What a page sends is validated
(lab_web.protocol); a bad frame gets an `error` frame back and changes nothing. Every request whose Host header does
not name this machine is refused first (DNS rebinding, see lab_web.access), then the page and the socket need the
token when one is set, and the socket an Origin that is the page's own.
"""
import asyncio
import itertools
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from aiohttp import WSMsgType, web

from lab_web.protocol import ProtocolError, frame, parse_command

UPDATES_PER_S = 25.0
MAX_SOCKET_MESSAGE_BYTES = 1 << 20
"""aiohttp closes the socket (code 1009) on a bigger message; smaller but oversized ones get an error frame."""
FLOOD_RATE_PER_S = 50.0
FLOOD_BURST = 100
"""A page may send 50 frames per second (bursts of 100); extra frames are dropped with one error per second."""
MAX_PENDING_REQUESTS = 2
"""Per page: service calls and model edits waiting for their reply."""
REQUEST_WORKERS = 4
"""Per kind of request (the service form's; the simulator's model edits and reset): threads that wait for
replies. When all of a kind's are busy, a further request of that kind is refused at once, so services that hang
cannot use up the threads the other kind, echo, camera and page departures need."""
FORM_REQUESTS = ("service_fields", "call_service")
HEARTBEAT_S = 5.0
SECURITY_HEADERS = {
    "Content-Security-Policy": "default-src 'self'; img-src 'self' data: blob:; connect-src 'self' ws: wss:; "
                               "style-src 'self' 'unsafe-inline'; frame-ancestors 'none'",
    "X-Content-Type-Options": "nosniff",
    "Referrer-Policy": "no-referrer",
}
REQUESTS = {
    "spawn_box": lambda bridge, args: bridge.spawn_box(args["x"], args["y"]),
    "move_model": lambda bridge, args: bridge.move_model(args["name"], args["x"], args["y"]),
    "delete_model": lambda bridge, args: bridge.delete_model(args["name"]),
    "reset_world": lambda bridge, args: bridge.reset_world(),
    "service_fields": lambda bridge, args: bridge.service_fields(args["service"]),
    "call_service": lambda bridge, args: bridge.call_service(args["service"], args["fields"]),
}
_session_ids = itertools.count(1)


class FloodGate:
    """A token bucket: `allow()` is False once a page sends faster than FLOOD_RATE_PER_S for a while."""

    def __init__(self, now_s):
        self._tokens, self._time = float(FLOOD_BURST), now_s
        self._last_warning = None

    def allow(self, now_s):
        self._tokens = min(FLOOD_BURST, self._tokens + (now_s - self._time) * FLOOD_RATE_PER_S)
        self._time = now_s
        if self._tokens >= 1.0:
            self._tokens -= 1.0
            return True
        return False

    def should_warn(self, now_s):
        if self._last_warning is None or now_s - self._last_warning >= 1.0:
            self._last_warning = now_s
            return True
        return False


class RequestPool:
    """Worker threads for one kind of request that refuse work when all are busy instead of queueing it (used
    from the event loop's thread only)."""

    def __init__(self, name, workers=REQUEST_WORKERS):
        self.name = name
        self.workers = workers
        self._free = workers
        self._executor = ThreadPoolExecutor(workers, thread_name_prefix="lab_web_" + name)

    def submit(self, function, *args):
        """An asyncio future of `function(*args)` in a worker, or None when every worker is busy."""
        if self._free == 0:
            return None
        self._free -= 1
        future = asyncio.get_running_loop().run_in_executor(self._executor, function, *args)
        future.add_done_callback(self._release)
        return future

    def _release(self, _future):
        self._free += 1

    def shutdown(self):
        self._executor.shutdown(wait=False, cancel_futures=True)


class PageSession:
    """One open page: what it has been sent, and its socket. `pools` maps a request type to its RequestPool."""

    def __init__(self, bridge, socket, pools):
        self.owner = "page-{}".format(next(_session_ids))
        self.bridge = bridge
        self.pools = pools
        self.socket = socket
        self.sent = {}            # Versioned attribute name -> version sent
        self.trail_cursor = None
        self.camera_on = False
        self.pending = 0
        self._send_lock = asyncio.Lock()

    async def send(self, text):
        async with self._send_lock:
            try:
                await self.socket.send_str(text)
            except ConnectionError:
                pass   # the page went away mid-send: the socket's handler ends the session

    def _changed(self, name):
        versioned = getattr(self.bridge, name)
        if versioned.value is None or self.sent.get(name) == versioned.version:
            return None
        self.sent[name] = versioned.version
        return versioned.value

    def frames(self):
        """The frames this page lacks now."""
        out = []
        world = self._changed("world")
        if world is not None:
            out.append(frame("world", **world))
        state = self._changed("state")
        if state is not None:
            reset, points, self.trail_cursor = self.bridge.trail_since(self.trail_cursor)
            out.append(frame("state", trail={"reset": reset, "points": points}, **state))
        turtlesim = self._changed("turtlesim")
        if turtlesim is not None:
            out.append(frame("turtlesim", **turtlesim))
        canvas = self._changed("canvas")
        if canvas is not None:
            out.append(frame("canvas", png=canvas))
        graph = self._changed("graph")
        if graph is not None:
            out.append(frame("graph", **graph))
        if self.camera_on:
            camera = self._changed("camera")
            if camera is not None:
                out.append(frame("camera", **camera))
        echo = self.bridge.echo_of(self.owner)
        if echo is not None and self.sent.get("echo") != (echo[0], echo[1].version):
            self.sent["echo"] = (echo[0], echo[1].version)
            out.append(frame("echo", topic=echo[0], text=echo[1].value))
        return out

    async def stream(self):
        """Send what changed, UPDATES_PER_S times a second at most, until the socket closes."""
        await self.send(frame("hello", **self.bridge.hello()))
        while not self.socket.closed:
            started = time.monotonic()
            for text in self.frames():
                await self.send(text)
            await asyncio.sleep(max(0.0, 1.0 / UPDATES_PER_S - (time.monotonic() - started)))

    async def handle(self, text):
        """One text frame from the page."""
        try:
            command = parse_command(text, self.bridge.teleop_limits)
        except ProtocolError as error:
            await self.refuse(error.request_id, str(error))
            return
        loop = asyncio.get_running_loop()
        if command.type == "teleop":
            self.bridge.command(self.owner, **command.args)
        elif command.type == "camera":
            self.camera_on = command.args["on"]
            self.sent.pop("camera", None)
            await loop.run_in_executor(None, self.bridge.set_camera, self.owner, self.camera_on)
        elif command.type == "echo":
            self.sent.pop("echo", None)
            try:
                await loop.run_in_executor(None, self.bridge.select_echo, self.owner, command.args["topic"])
            except Exception as error:   # noqa: BLE001 - any failure is reported to the page, the server lives on
                await self.refuse(None, "echo: {}".format(error))
        elif self.pending >= MAX_PENDING_REQUESTS:
            await self.refuse(command.id, "busy: wait for the reply to an earlier request")
        else:
            pool = self.pools[command.type]
            future = pool.submit(REQUESTS[command.type], self.bridge, command.args)
            if future is None:
                await self.refuse(command.id, "busy: {} {} requests are waiting for their services to answer; try "
                                              "again in a moment".format(pool.workers, pool.name))
                return
            self.pending += 1
            asyncio.ensure_future(self._request(command, future))

    async def _request(self, command, future):
        try:
            result = await future
            await self.send(frame("reply", id=command.id, ok=True, text=result))
        except Exception as error:   # noqa: BLE001 - a failed request is a reply, never a dead server
            await self.refuse(command.id, str(error) or type(error).__name__)
        finally:
            self.pending -= 1

    async def refuse(self, request_id, text):
        if self.socket.closed:
            return
        if request_id is None:
            await self.send(frame("error", text=text))
        else:
            await self.send(frame("reply", id=request_id, ok=False, text=text))


def _same_origin(request):
    """A browser sends Origin with every WebSocket; another site's page must not drive this robot."""
    origin = request.headers.get("Origin")
    if origin is None:
        return True
    return origin.split("://", 1)[-1].rstrip("/") == request.host


def make_app(bridge, policy, static_dir):
    """The aiohttp application serving `static_dir` and the bridge to pages that `policy` admits."""
    static_dir = Path(static_dir)
    sessions = set()
    form_pool, model_pool = RequestPool("service form"), RequestPool("simulator")
    pools = {kind: form_pool if kind in FORM_REQUESTS else model_pool for kind in REQUESTS}

    def refused(text):
        return web.Response(status=403, text="lab_web: " + text + "\n")

    @web.middleware
    async def known_host(request, handler):
        if not policy.allows_host(request.headers.get("Host")):
            return refused("the Host header {!r} does not name this machine: open the URL lab_web printed "
                           "(localhost or 127.0.0.1)".format(request.headers.get("Host", "")))
        return await handler(request)

    async def index(request):
        if not policy.allows(request.query.get("token")):
            return refused("this page needs the token printed where lab_web started: open http://<host>:<port>/"
                           "?token=<token>")
        return web.FileResponse(static_dir / "index.html", headers={**SECURITY_HEADERS, "Cache-Control": "no-store"})

    async def socket(request):
        if not policy.allows(request.query.get("token")):
            return refused("the WebSocket needs the page's token")
        if not _same_origin(request):
            return refused("the WebSocket accepts only pages served by lab_web itself")
        ws = web.WebSocketResponse(max_msg_size=MAX_SOCKET_MESSAGE_BYTES, heartbeat=HEARTBEAT_S)
        await ws.prepare(request)
        session = PageSession(bridge, ws, pools)
        sessions.add(session)
        streamer = asyncio.ensure_future(session.stream())
        flood = FloodGate(time.monotonic())
        try:
            async for message in ws:
                now = time.monotonic()
                if message.type not in (WSMsgType.TEXT, WSMsgType.BINARY):
                    continue
                if not flood.allow(now):
                    if flood.should_warn(now):
                        await session.refuse(None, "too many messages: at most {:g} per second, extra ones are "
                                                    "dropped".format(FLOOD_RATE_PER_S))
                elif message.type == WSMsgType.BINARY:
                    await session.refuse(None, "binary frames are not accepted: send JSON text")
                else:
                    await session.handle(message.data)
        finally:
            sessions.discard(session)
            streamer.cancel()
            await asyncio.get_running_loop().run_in_executor(None, bridge.disconnect, session.owner)
        return ws

    async def close_pages(app):
        for session in list(sessions):
            await session.socket.close(message=b"lab_web is shutting down")

    async def stop_pools(app):
        for pool in (form_pool, model_pool):
            pool.shutdown()

    app = web.Application(client_max_size=64 * 1024, middlewares=[known_host])
    app.router.add_get("/", index)
    app.router.add_get("/ws", socket)
    app.router.add_static("/static/", static_dir, show_index=False, follow_symlinks=False)
    app.on_shutdown.append(close_pages)
    app.on_cleanup.append(stop_pools)
    return app
