"""lab_web when the ROS graph misbehaves: a service whose callback never returns does not stall the other pages'
requests (each kind of request has its own few workers and the form's calls a timeout, after which the page is
told which service did not answer); after roscore and then the simulator are restarted, the page's pose and teleop
come back by themselves (lab_web re-registers, as the lab's other nodes do); a teleop frame holding a 309-digit
integer gets an error and the page stays connected."""
import asyncio
import json
import time

import aiohttp
import pytest

from roslab import wait_for_service, wait_until

from .conftest import start_web_server

SERVICE_TIMEOUT_S = 3.0
STUCK_NODE = """\
#!/usr/bin/env python3
import threading

import rospy
from std_srvs.srv import Trigger


def never_answer(_request):
    threading.Event().wait()


rospy.init_node("stuck_node")
rospy.Service("stuck_service", Trigger, never_answer)
rospy.spin()
"""
ANSWERED_WITHIN_S = 10.0
RECOVER_WITHIN_S = 12.0   # the lab's other nodes: within 10 s of a restart
SIMULATOR = ("tb3_sim", "tb3_sim.launch", "gui:=false", "real_time_factor:=5")


@pytest.fixture(scope="module")
def web(ros_master, tmp_path_factory):
    """tb3_sim at 5x, a node whose service never answers, and lab_web with a 3 s form-call timeout: (the page's
    WebSocket URL, lab_web's process, the simulator's process)."""
    simulator = ros_master.roslaunch(*SIMULATOR)
    wait_for_service(ros_master.uri, "/gazebo/reset_world", timeout_s=60)
    stuck = tmp_path_factory.mktemp("stuck") / "stuck_node.py"
    stuck.write_text(STUCK_NODE)
    ros_master.start(["python3", str(stuck)], "stuck_node")
    wait_for_service(ros_master.uri, "/stuck_service")
    base, process = start_web_server(ros_master, "_service_timeout:={}".format(SERVICE_TIMEOUT_S))
    return base.replace("http", "ws") + "ws", process, simulator


class Page:
    """One open page: its socket, the frames it got (by type) and its requests' replies (by id)."""

    def __init__(self, ws):
        self.ws = ws
        self.replies = {}
        self.frames = []
        self._ids = iter(range(1, 1000))
        self._reader = asyncio.ensure_future(self._read())

    async def _read(self):
        async for message in self.ws:
            content = json.loads(message.data)
            self.frames.append(content)
            if content["type"] == "reply":
                self.replies[content["id"]] = content

    async def request(self, kind, **args):
        request_id = next(self._ids)
        await self.ws.send_str(json.dumps({"type": kind, "id": request_id, **args}))
        return request_id

    async def reply(self, request_id, timeout_s):
        deadline = time.monotonic() + timeout_s
        while request_id not in self.replies:
            assert time.monotonic() < deadline, "no reply to request {} within {} s".format(request_id, timeout_s)
            await asyncio.sleep(0.05)
        return self.replies[request_id]

    def latest(self, kind):
        return next((content for content in reversed(self.frames) if content["type"] == kind), None)

    async def close(self):
        await self.ws.close()
        self._reader.cancel()


async def open_page(session, url):
    page = Page(await session.ws_connect(url))
    deadline = time.monotonic() + 20
    while page.latest("state") is None or page.latest("state")["robot"] is None:
        assert time.monotonic() < deadline, "no robot state on the page"
        await asyncio.sleep(0.1)
    return page


async def stuck_calls_leave_other_requests_answered(url):
    async with aiohttp.ClientSession() as session:
        stuck_pages = [await open_page(session, url) for _ in range(3)]
        stuck = [(page, await page.request("call_service", service="/stuck_service", fields={}))
                 for page in stuck_pages for _ in range(2)]   # two each: a page's own limit
        await asyncio.sleep(0.5)
        other = await open_page(session, url)
        started = time.monotonic()
        reset = await other.reply(await other.request("reset_world"), ANSWERED_WITHIN_S)
        spawned = await other.reply(await other.request("spawn_box", x=1.5, y=1.5), ANSWERED_WITHIN_S)
        await other.ws.send_str(json.dumps({"type": "echo", "topic": "/odom"}))
        await other.ws.send_str(json.dumps({"type": "camera", "on": True}))
        deadline = time.monotonic() + ANSWERED_WITHIN_S
        while other.latest("echo") is None or other.latest("camera") is None:
            assert time.monotonic() < deadline, "echo and camera frames while the stuck calls wait"
            await asyncio.sleep(0.1)
        others_answered_s = time.monotonic() - started
        stuck_replies = [await page.reply(request_id, SERVICE_TIMEOUT_S + ANSWERED_WITHIN_S)
                         for page, request_id in stuck]
        after = await other.reply(await other.request("call_service", service="/gazebo/get_world_properties",
                                                      fields={}), ANSWERED_WITHIN_S)
        for page in stuck_pages + [other]:
            await page.close()
    return reset, spawned, others_answered_s, stuck_replies, after


def test_a_service_that_never_answers_leaves_the_other_requests_answered(web):
    reset, spawned, others_answered_s, stuck_replies, after = asyncio.run(
        stuck_calls_leave_other_requests_answered(web[0]))
    assert reset["ok"] and spawned["ok"], (reset, spawned)
    assert others_answered_s < SERVICE_TIMEOUT_S, "answered while the stuck calls still waited"
    timed_out = "/stuck_service did not answer within {:g} s".format(SERVICE_TIMEOUT_S)
    assert all(not reply["ok"] for reply in stuck_replies)
    assert sum(timed_out in reply["text"] for reply in stuck_replies) >= 4, stuck_replies
    assert all(timed_out in reply["text"] or reply["text"].startswith("busy:") for reply in stuck_replies)
    assert after["ok"] and "model_names" in after["text"], after


async def huge_integer_teleop(url):
    async with aiohttp.ClientSession() as session:
        page = await open_page(session, url)
        huge = "1" + "0" * 308
        await page.ws.send_str('{"type": "teleop", "target": "robot", "linear": %s, "angular": 0}' % huge)
        reply = await page.reply(await page.request("reset_world"), ANSWERED_WITHIN_S)
        closed = page.ws.closed
        await page.close()
    return [content["text"] for content in page.frames if content["type"] == "error"], reply, closed


def test_a_309_digit_teleop_number_gets_an_error_and_the_page_stays(web):
    errors, reply, closed = asyncio.run(huge_integer_teleop(web[0]))
    assert any(text.startswith("linear must be a finite number within") for text in errors), errors
    assert reply["ok"] and not closed
    assert "Traceback" not in web[1].output() and "OverflowError" not in web[1].output()


def restart_roscore_and_simulator(ros_master, simulator):
    """What a student does after a crash: roscore again, then the simulator again (a new process)."""
    simulator.stop()
    ros_master.restart_core()
    ros_master.roslaunch(*SIMULATOR)
    wait_for_service(ros_master.uri, "/gazebo/reset_world", timeout_s=60)


async def drive_after_restart(url, restart):
    """Seconds from the restarted simulator's services to the page seeing the robot move under its teleop (None:
    not within RECOVER_WITHIN_S + 10 s)."""
    async with aiohttp.ClientSession() as session:
        page = await open_page(session, url)
        await asyncio.get_running_loop().run_in_executor(None, restart)
        restarted = time.monotonic()
        start = page.latest("state")["robot"]
        moved = None
        while time.monotonic() - restarted < RECOVER_WITHIN_S + 10:
            await page.ws.send_str(json.dumps({"type": "teleop", "target": "robot", "linear": 0.2, "angular": 0}))
            await asyncio.sleep(0.1)
            robot = page.latest("state")["robot"]
            if abs(robot["x"] - start["x"]) + abs(robot["y"] - start["y"]) > 0.05:
                moved = time.monotonic() - restarted
                break
        await page.ws.send_str(json.dumps({"type": "teleop", "target": "robot", "linear": 0, "angular": 0}))
        await page.close()
    return moved


def test_after_a_roscore_and_simulator_restart_the_page_drives_the_robot_again(ros_master, web):
    url, _, simulator = web
    moved_after_s = asyncio.run(drive_after_restart(url, lambda: restart_roscore_and_simulator(ros_master, simulator)))
    assert moved_after_s is not None and moved_after_s < RECOVER_WITHIN_S, moved_after_s
    wait_until(lambda: "re-registered with a restarted ROS master" in web[1].output(), 10,
               "lab_web to say it re-registered")
