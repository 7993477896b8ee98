"""Test helpers for a real ROS 1 graph: a private master per test module, node and launch processes that
are always ended, waiting with timeouts, and a probe node that reads and writes topics for the test."""
from roslab.http_check import http_status
from roslab.master import RosMaster, private_master
from roslab.ports import free_port
from roslab.probe import TopicProbe
from roslab.processes import RosProcess, stop_together
from roslab.waiting import (
    service_uri,
    wait_for_param,
    wait_for_service,
    wait_for_service_gone,
    wait_for_topic,
    wait_until,
)

__all__ = ["RosMaster", "RosProcess", "TopicProbe", "free_port", "http_status", "private_master", "service_uri",
           "stop_together", "wait_for_param", "wait_for_service", "wait_for_service_gone", "wait_for_topic",
           "wait_until"]
