"""A real headless browser for page tests: Debian's Chromium driven by Selenium through chromedriver, with its
console log, canvas pixels and a guaranteed end (every Chromium process it started is gone after `quit`)."""
import os
import time

import cv2
import numpy
from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By

from roslab.processes import descendants, kill_if_alive

CHROMEDRIVER = "/usr/bin/chromedriver"
WINDOW_SIZE = (1400, 1000)
NETWORK_NOISE = ("WebSocket connection to", "favicon.ico")
"""Console entries Chromium itself writes about the network (a socket retried while a server restarts); page code
cannot prevent them, so they are not counted as the page's errors."""


class HeadlessBrowser:
    def __init__(self):
        options = webdriver.ChromeOptions()
        for argument in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                         "--window-size={},{}".format(*WINDOW_SIZE), "--disable-extensions",
                         "--no-first-run", "--disable-background-networking"):
            options.add_argument(argument)
        options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
        self._service = Service(CHROMEDRIVER)
        self.driver = webdriver.Chrome(service=self._service, options=options)
        self._processes = self._started()

    def _started(self):
        """chromedriver and every Chromium process under it, as {(pid, start time)}."""
        driver_pid = self._service.process.pid
        return ({process for process in descendants(os.getpid()) if process[0] == driver_pid}
                | descendants(driver_pid))

    def console_errors(self):
        """SEVERE console entries since the last call, except Chromium's own network noise."""
        return [entry for entry in self.driver.get_log("browser")
                if entry["level"] == "SEVERE" and not any(noise in entry["message"] for noise in NETWORK_NOISE)]

    def script(self, code, *args):
        return self.driver.execute_script(code, *args)

    def js_heap_bytes(self):
        """The page's used JavaScript heap after a full garbage collection (Chrome DevTools' JSHeapUsedSize)."""
        self.driver.execute_cdp_cmd("Performance.enable", {})
        self.driver.execute_cdp_cmd("HeapProfiler.collectGarbage", {})
        metrics = self.driver.execute_cdp_cmd("Performance.getMetrics", {})["metrics"]
        return next(metric["value"] for metric in metrics if metric["name"] == "JSHeapUsedSize")

    def canvas_pixels(self, element_id):
        """A screenshot of element `element_id` as the browser rendered it on screen, an RGB numpy array (rows,
        columns, 3) in CSS pixels (the headless window's device pixel ratio is 1)."""
        png = self.driver.find_element(By.ID, element_id).screenshot_as_png
        return cv2.cvtColor(cv2.imdecode(numpy.frombuffer(png, numpy.uint8), cv2.IMREAD_COLOR), cv2.COLOR_BGR2RGB)

    def save_screenshot(self, path):
        self.driver.save_screenshot(str(path))

    def save_full_page(self, path):
        """A screenshot of the whole page: the window made as tall as the page (same width), scrolled to the top."""
        for _ in range(3):
            inner, full = self.script("return [window.innerHeight, document.documentElement.scrollHeight];")
            if full <= inner:
                break
            size = self.driver.get_window_size()
            self.driver.set_window_size(size["width"], size["height"] + full - inner)
        self.script("window.scrollTo(0, 0);")
        time.sleep(0.5)   # a frame or two drawn at the new size
        self.save_screenshot(path)

    def quit(self):
        self._processes |= self._started()
        try:
            self.driver.quit()
        finally:
            for pid, started in self._processes:
                kill_if_alive(pid, started)
