"""lab_web's test fixtures: the web server as a user starts it (rosrun lab_web web_server, on a free port) and a
real headless Chromium to open its page."""

import pytest

from roslab import free_port, http_status, wait_until
from roslab.browser import HeadlessBrowser


def start_web_server(ros_master, *params):
    """Start lab_web's server with private `params` (`_host:=0.0.0.0`, ...); returns (its base URL, process)."""
    port = free_port()
    process = ros_master.rosrun("lab_web", "web_server", "_port:={}".format(port), *params)
    base = "http://127.0.0.1:{}/".format(port)
    wait_until(lambda: http_status(base + "static/app.js") == 200 or not process.running(), 30, "lab_web to serve")
    assert process.running(), process.output()
    return base, process


@pytest.fixture(scope="module")
def browser():
    chromium = HeadlessBrowser()
    yield chromium
    chromium.quit()


def open_page(browser, url, ready="labView.connected"):
    """Load `url` and wait until the page's `ready` JavaScript expression is true."""
    browser.driver.get(url)
    wait_until(lambda: browser.script("return typeof labView !== 'undefined' && !!({});".format(ready)), 30,
               "the page: " + ready)
