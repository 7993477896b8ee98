"""The web server (aiohttp): the page at /, its files under /static/, and one WebSocket per open page at /ws.

No ROS import: it talks to a bridge (lab_web.ros_bridge.RosBridge: its panels, their command registry, hello,
handle and disconnect). Each page gets at most UPDATES_PER_S rounds of frames per second, only what changed since
its last round, and a slow page simply gets fewer (each send waits for the previous one). What a page sends is
validated against the panels' command registry (lab_web.commands); a bad frame gets an `error` frame back and
changes nothing. Every request whose Host header does not name this machine is refused first (DNS rebinding, see
lab_web.access), then the page and the socket need the token when one is set, and the socket an Origin that is the
page's own.
"""
import asyncio
import itertools
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from aiohttp import WSMsgType, web

from lab_web.commands import ProtocolError, parse_command
from lab_web.protocol import frame

UPDATES_PER_S = 25.0
MAX_SOCKET_MESSAGE_BYTES = 1 << 20
"""aiohttp closes the socket (code 1009) on a bigger message; smaller but oversized ones get an error frame."""
FLOOD_RATE_PER_S = 50.0
FLOOD_BURST = 100
"""A page may send 50 frames per second (bursts of 100); extra frames are dropped with one error per second."""
MAX_PENDING_REQUESTS = 2
"""Per page: service calls and model edits waiting for their reply."""
REQUEST_WORKERS = 4
"""Per kind of request (CommandSpec.pool: the service form's; the simulator's model edits and reset): threads
that wait for replies. When all of a kind's are busy, a further request of that kind is refused at once, so
services that hang cannot use up the threads the other kind, echo, camera and page departures need."""
INLINE_COMMANDS = ("teleop",)
"""Commands cheap enough to run in the event loop; the other commands without a reply run in its executor."""
HEARTBEAT_S = 5.0
SECURITY_HEADERS = {
    "Content-Security-Policy": "default-src 'self'; img-src 'self' data: blob:; connect-src 'self' ws: wss:; "
                               "style-src 'self' 'unsafe-inline'; frame-ancestors 'none'",
    "X-Content-Type-Options": "nosniff",
    "Referrer-Policy": "no-referrer",
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
    """One open page: what it has been sent, and its socket. `pools` maps a pool name (CommandSpec.pool) to its
    RequestPool."""

    def __init__(self, bridge, socket, pools):
        self.owner = "page-{}".format(next(_session_ids))
        self.bridge = bridge
        self.pools = pools
        self.socket = socket
        self.sent = {}            # key -> what was sent of it (a Versioned's version)
        self.trail_cursor = None
        self.pending = 0
        self._send_lock = asyncio.Lock()

    async def send(self, text):
        async with self._send_lock:
            try:
                await self.socket.send_str(text)
            except ConnectionError:
                pass   # the page went away mid-send: the socket's handler ends the session

    def lacks(self, key, versioned):
        """`versioned`'s value when this page has not been sent it yet (under `key`), else None."""
        value, version = versioned.value, versioned.version
        if value is None or self.sent.get(key) == version:
            return None
        self.sent[key] = version
        return value

    def frames(self):
        """The frames this page lacks now, panel by panel."""
        return [frame(kind, **content) for panel in self.bridge.panels for kind, content in panel.frames(self)]

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
            command = parse_command(text, self.bridge.commands)
        except ProtocolError as error:
            await self.refuse(error.request_id, str(error))
            return
        spec = self.bridge.commands[command.type]
        if not spec.request:
            try:
                if command.type in INLINE_COMMANDS:
                    self.bridge.handle(self, command)
                else:
                    await asyncio.get_running_loop().run_in_executor(None, self.bridge.handle, self, command)
            except Exception as error:   # noqa: BLE001 - any failure is reported to the page, the server lives on
                await self.refuse(None, "{}: {}".format(command.type, error))
        elif self.pending >= MAX_PENDING_REQUESTS:
            await self.refuse(command.id, "busy: wait for the reply to an earlier request")
        else:
            pool = self.pools[spec.pool]
            future = pool.submit(self.bridge.handle, self, command)
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
    pools = {spec.pool: RequestPool(spec.pool) for spec in bridge.commands.values() if spec.request}

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
        # No permessage-deflate: on loopback it only spends the server's CPU (aiohttp deflates every frame in the
        # event loop) on text that is mostly base64 and barely shrinks.
        ws = web.WebSocketResponse(max_msg_size=MAX_SOCKET_MESSAGE_BYTES, heartbeat=HEARTBEAT_S, compress=False)
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
        for pool in pools.values():
            pool.shutdown()

    app = web.Application(client_max_size=64 * 1024, middlewares=[known_host])
    app.router.add_get("/", index)
    app.router.add_get("/ws", socket)
    app.router.add_static("/static/", static_dir, show_index=False, follow_symlinks=False)
    app.on_shutdown.append(close_pages)
    app.on_cleanup.append(stop_pools)
    return app
