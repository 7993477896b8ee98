"""Safety of the web view against tb3_sim: a page that goes away (tab closed, browser killed) stops the robot
within half a second, and hundreds of malformed or hostile WebSocket frames get errors back, leave the server
serving and never move the robot."""
import asyncio
import json
import random
import signal
import subprocess
import sys
import time

import aiohttp
import pytest
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys

from roslab import http_status, wait_for_service, wait_until
from roslab.robot_view import RobotView, pose_of

from .conftest import open_page, start_web_server

STOP_WITHIN_S = 0.5
SEED = 20261124
TELEOP_CLIENT = """
import asyncio, json, sys, aiohttp
async def drive(url):
    async with aiohttp.ClientSession() as session:
        async with session.ws_connect(url) as ws:
            while True:
                await ws.send_str(json.dumps({"type": "teleop", "target": "robot", "linear": 0.2, "angular": 0}))
                print("sent", flush=True)
                await asyncio.sleep(0.1)
asyncio.run(drive(sys.argv[1]))
"""


@pytest.fixture(scope="module")
def robot(ros_master):
    ros_master.roslaunch("tb3_sim", "tb3_sim.launch", "gui:=false")
    wait_for_service(ros_master.uri, "/gazebo/reset_world", timeout_s=60)
    view = RobotView(ros_master.probe())
    view.probe.subscribe("/cmd_vel", "geometry_msgs/Twist")
    return view


@pytest.fixture(scope="module")
def web(ros_master, robot):
    return start_web_server(ros_master)


def first_zero_after(robot, started):
    """Wall time of the first zero /cmd_vel at or after `started` (waits up to 5 s for it)."""
    def zero(message):
        return message["wall"] >= started and message["msg"]["linear"]["x"] == 0.0
    found = []
    wait_until(lambda: found.extend(m for m in robot.probe.take("/cmd_vel") if zero(m)) or found, 5,
               "a zero /cmd_vel")
    return found[0]["wall"]


@pytest.mark.realtime   # half a second of wall time from a closed tab to the stop
def test_closing_the_tab_stops_the_robot_within_half_a_second(robot, web, browser):
    base, _ = web
    browser.driver.switch_to.new_window("tab")
    open_page(browser, base, "labView.connected && labView.robot")
    body = browser.driver.find_element(By.TAG_NAME, "body")
    ActionChains(browser.driver).key_down(Keys.ARROW_UP, body).perform()
    robot.probe.wait_for_message("/odom", 10, lambda odom: odom["twist"]["twist"]["linear"]["x"] > 0.1)
    robot.probe.take("/cmd_vel")
    closed_at = time.time()
    browser.driver.close()   # with the key still held
    browser.driver.switch_to.window(browser.driver.window_handles[0])
    assert first_zero_after(robot, closed_at) - closed_at <= STOP_WITHIN_S
    robot.settled_pose()


@pytest.mark.realtime   # half a second of wall time from a killed client to the stop
def test_a_client_that_dies_mid_drive_stops_the_robot_within_half_a_second(robot, web):
    base, _ = web
    client = subprocess.Popen([sys.executable, "-c", TELEOP_CLIENT, base.replace("http", "ws") + "ws"],
                              stdout=subprocess.PIPE, text=True)
    try:
        robot.probe.wait_for_message("/odom", 10, lambda odom: odom["twist"]["twist"]["linear"]["x"] > 0.1)
        robot.probe.take("/cmd_vel")
        killed_at = time.time()
        client.send_signal(signal.SIGKILL)
    finally:
        client.kill()
        client.wait()
    assert first_zero_after(robot, killed_at) - killed_at <= STOP_WITHIN_S
    robot.settled_pose()


def hostile_frames(rng):
    """At least 200 frames no page of ours sends: garbage, wrong shapes, wrong types, out-of-range values,
    injection-looking names, oversized and deeply nested JSON. Each is (kind, payload): kind "text" or "bytes"."""
    frames = [("bytes", bytes(rng.getrandbits(8) for _ in range(rng.randint(1, 200)))) for _ in range(50)]
    frames += [("text", "".join(chr(rng.randint(1, 0xD7FF)) for _ in range(rng.randint(1, 100)))) for _ in range(50)]
    frames += [("text", text) for text in ("", "{", "}", "null", "[]", "42", '"teleop"', "{'type': 'teleop'}",
                                           "[" * 5000, "{\"a\":" * 3000, " " * 5000, "x" * 200000)]
    bad_values = [None, "1", [], {}, True, 1e9, -1e300, "NaN", 2 ** 70]
    for value in bad_values:
        frames.append(("json", {"type": "teleop", "target": "robot", "linear": value, "angular": 0}))
        frames.append(("json", {"type": "teleop", "target": "robot", "linear": 0, "angular": value}))
        frames.append(("json", {"type": "teleop", "target": value, "linear": 0.1, "angular": 0}))
        frames.append(("json", {"type": "spawn_box", "id": 1, "x": value, "y": 0}))
        frames.append(("json", {"type": "move_model", "id": 2, "name": value, "x": 0, "y": 0}))
        frames.append(("json", {"type": "delete_model", "id": value, "name": "box"}))
        frames.append(("json", {"type": "call_service", "id": 3, "service": value, "fields": {}}))
        frames.append(("json", {"type": "call_service", "id": 4, "service": "/gazebo/reset_world", "fields": value}))
        frames.append(("json", {"type": "echo", "topic": value if value is not None else 5}))
        frames.append(("json", {"type": "camera", "on": value}))
        frames.append(("json", {"type": value}))
    for name in ("../../etc/passwd", "/cmd_vel; rosnode kill -a", "$(reboot)", "a" * 500, "<script>", "robot\n"):
        frames.append(("json", {"type": "delete_model", "id": 5, "name": name}))
        frames.append(("json", {"type": "echo", "topic": name}))
    frames += [("text", "NaN"), ("text", '{"type": "teleop", "target": "robot", "linear": Infinity, "angular": 0}')]
    frames += [("json", {"type": "teleop", "target": "robot", "linear": 0.27, "angular": 0}),
               ("json", {"type": "teleop", "target": "turtle1", "linear": -2.5, "angular": 0})]
    rng.shuffle(frames)
    return frames


async def send_hostile_frames(url, frames):
    """Send every frame (reconnecting when the server closes a socket, as it does for a 200 kB frame); returns
    (frames sent, error or failed reply frames received, sockets closed by the server)."""
    sent = refused = closed = 0
    async with aiohttp.ClientSession() as session:
        ws = await session.ws_connect(url, max_msg_size=0)
        for kind, payload in frames:
            if ws.closed:
                closed += 1
                ws = await session.ws_connect(url, max_msg_size=0)
            try:
                if kind == "bytes":
                    await ws.send_bytes(payload)
                else:
                    await ws.send_str(payload if kind == "text" else json.dumps(payload))
                sent += 1
            except ConnectionResetError:
                closed += 1
                continue
            await asyncio.sleep(0.03)   # below the flood limit: every frame deserves its own answer
        deadline = time.monotonic() + 5
        while time.monotonic() < deadline and not ws.closed:
            try:
                message = await ws.receive(timeout=max(0.1, deadline - time.monotonic()))
            except asyncio.TimeoutError:
                break
            if message.type != aiohttp.WSMsgType.TEXT:
                continue
            answer = json.loads(message.data)
            refused += answer["type"] == "error" or (answer["type"] == "reply" and not answer["ok"])
        await ws.close()
    return sent, refused, closed


def test_hostile_frames_leave_the_server_serving_and_the_robot_still(robot, web):
    base, process = web
    before = pose_of(robot.probe.wait_for_message("/odom"))
    robot.probe.take("/cmd_vel")
    frames = hostile_frames(random.Random(SEED))
    assert len(frames) >= 200
    sent, refused, closed = asyncio.run(send_hostile_frames(base.replace("http", "ws") + "ws", frames))
    assert process.running()
    assert sent >= 200 and closed <= 1
    assert refused >= 150, "most hostile frames are answered with an error"   # the last socket's answers counted
    assert all(message["msg"]["linear"]["x"] == 0.0 and message["msg"]["angular"]["z"] == 0.0
               for message in robot.probe.take("/cmd_vel"))
    after = pose_of(robot.probe.wait_for_message("/odom"))
    assert abs(after[0] - before[0]) < 1e-3 and abs(after[1] - before[1]) < 1e-3
    assert http_status(base) == 200


def test_a_flood_is_cut_to_the_rate_limit_with_an_error(web):
    base, process = web

    async def flood():
        async with aiohttp.ClientSession() as session:
            async with session.ws_connect(base.replace("http", "ws") + "ws") as ws:
                for _ in range(400):
                    await ws.send_str('{"type": "echo", "topic": null}')
                texts = []
                deadline = time.monotonic() + 3
                while time.monotonic() < deadline:
                    try:
                        message = await ws.receive(timeout=0.5)
                    except asyncio.TimeoutError:
                        break
                    answer = json.loads(message.data)
                    if answer["type"] == "error":
                        texts.append(answer["text"])
                return texts
    texts = asyncio.run(flood())
    assert any(text.startswith("too many messages") for text in texts)
    assert process.running()
