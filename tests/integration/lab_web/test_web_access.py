"""Who may open the page: anyone on this machine by default; beyond loopback (`_host:=0.0.0.0`) the server warns
and needs the printed token, for the page and for the WebSocket; another site's page may never use the socket.
The tests of the default (loopback) server share one: each asks it something a fresh one would answer the same way,
and starting one costs 2 CPU s."""
import asyncio
import json
import re
import socket

import aiohttp
import pytest

from roslab import free_port, http_status, wait_until

from .conftest import open_page, start_web_server


async def socket_status(url, **headers):
    """The HTTP status a WebSocket handshake to `url` gets (101 once upgraded), with the first frame's type."""
    async with aiohttp.ClientSession() as session:
        try:
            async with session.ws_connect(url, headers=headers) as ws:
                first = await ws.receive(timeout=10)
                return 101, json.loads(first.data)["type"]
        except aiohttp.WSServerHandshakeError as error:
            return error.status, None


def raw_status(base, path, host, **headers):
    """The status code of a GET of `path` written by hand, with the given Host header (a browser on a rebound
    DNS name sends its own name there)."""
    port = int(base.rsplit(":", 1)[1].strip("/"))
    headers = {"Connection": "close", **headers}
    lines = ["GET {} HTTP/1.1".format(path), "Host: " + host, *("{}: {}".format(*h) for h in headers.items()), "", ""]
    with socket.create_connection(("127.0.0.1", port), timeout=10) as raw:
        raw.sendall("\r\n".join(lines).encode())
        return int(raw.recv(4096).split(b" ", 2)[1])


@pytest.fixture(scope="module")
def loopback_server(ros_master):
    """(base URL, process) of one web server with the default settings, for the module's tests."""
    return start_web_server(ros_master)


WEBSOCKET_UPGRADE = {"Upgrade": "websocket", "Connection": "Upgrade", "Sec-WebSocket-Version": "13",
                     "Sec-WebSocket-Key": "dGhlIHNhbXBsZSBub25jZQ=="}


def test_a_dns_rebinding_page_is_refused(loopback_server):
    """Host and Origin agree, as they do for a page on a name its attacker re-pointed at 127.0.0.1: refused, for
    the page and the socket; the same requests with this machine's names are served."""
    base, _ = loopback_server
    port = base.rsplit(":", 1)[1].strip("/")
    evil = "evil.example:" + port
    assert raw_status(base, "/", evil) == 403
    assert raw_status(base, "/static/app.js", evil) == 403
    assert raw_status(base, "/ws", evil, Origin="http://" + evil, **WEBSOCKET_UPGRADE) == 403
    for host in ("localhost:" + port, "127.0.0.1:" + port, "[::1]:" + port):
        assert raw_status(base, "/", host) == 200
        assert raw_status(base, "/ws", host, Origin="http://" + host, **WEBSOCKET_UPGRADE) == 101


def test_on_loopback_the_page_opens_without_a_token(loopback_server, browser):
    base, _ = loopback_server
    assert http_status(base) == 200
    assert asyncio.run(socket_status(base.replace("http", "ws") + "ws")) == (101, "hello")
    open_page(browser, base)


def test_beyond_loopback_the_token_is_required(ros_master, browser):
    base, process = start_web_server(ros_master, "_host:=0.0.0.0")
    wait_until(lambda: "token=" in process.output(), 10, "the URL with its token")
    output = process.output()
    token = re.search(r"\?token=([\w-]+)", output).group(1)
    assert "anyone who can reach it and has the token can drive the robot" in output
    assert http_status(base) == 403
    assert http_status(base + "?token=wrong-token") == 403
    ws = base.replace("http", "ws") + "ws"
    assert asyncio.run(socket_status(ws)) == (403, None)
    assert asyncio.run(socket_status(ws + "?token=" + token)) == (101, "hello")
    browser.driver.get(base)
    assert "needs the token" in browser.driver.page_source
    open_page(browser, base + "?token=" + token)
    process.stop()   # not left to follow a simulator a later test starts


@pytest.mark.parametrize("origin", ["http://evil.example", "http://localhost:1"])
def test_another_sites_page_cannot_open_the_socket(loopback_server, origin):
    base, _ = loopback_server
    assert asyncio.run(socket_status(base.replace("http", "ws") + "ws", Origin=origin)) == (403, None)


def test_a_taken_port_is_reported_with_the_argument_that_changes_it(ros_master, loopback_server):
    base, first = loopback_server
    port = base.rsplit(":", 1)[1].strip("/")
    second = ros_master.rosrun("lab_web", "web_server", "__name:=lab_web_2", "_port:=" + port)
    assert second.popen.wait(timeout=30) == 1
    assert "Choose another with port:=<number>" in second.output()
    assert first.running() and http_status(base) == 200


def test_tb3_sim_launch_serves_the_page_with_web_true(ros_master, browser):
    port = free_port()
    ros_master.roslaunch("tb3_sim", "tb3_sim.launch", "gui:=false", "web:=true", "web_port:={}".format(port))
    base = "http://127.0.0.1:{}/".format(port)
    wait_until(lambda: http_status(base) == 200, 60, "tb3_sim.launch web:=true to serve the page")
    open_page(browser, base, "labView.connected && labView.robot")
