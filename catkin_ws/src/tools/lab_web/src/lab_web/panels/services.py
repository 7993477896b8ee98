"""The service panel (the Week 4 form): any service with a plain request, its fields read from its type."""
import json

import rosservice

from lab_web import commands, service_form
from lab_web.panels.base import Panel
from lab_web.ros_context import BridgeError

FORM = "service form"
"""The worker pool of the form's requests (a hanging service must not hold up the simulator's)."""


class ServicesPanel(Panel):
    name = "services"
    COMMANDS = {
        "service_fields": commands.CommandSpec((("service", commands.name),),
                                               "reply text: JSON [{\"name\", \"type\"}] of the request's fields", FORM),
        "call_service": commands.CommandSpec((("service", commands.name), ("fields", commands.field_values)),
                                             "fields: {name: value}; reply text: the response as YAML-like text",
                                             FORM),
    }

    def handle(self, session, kind, args):
        if kind == "service_fields":
            return self._fields(args["service"])
        return self._call(args["service"], args["fields"])

    @staticmethod
    def _service_class(service):
        try:
            return rosservice.get_service_class_by_name(service)
        except (rosservice.ROSServiceException, rosservice.ROSServiceIOException, OSError) as error:
            raise BridgeError("{}: {}".format(service, str(error) or "not available")) from None

    def _fields(self, service):
        try:
            return json.dumps(service_form.request_fields(self._service_class(service)._request_class))
        except service_form.FormError as error:
            raise BridgeError(str(error)) from None

    def _call(self, service, values):
        service_class = self._service_class(service)
        try:
            request = service_class._request_class(**service_form.request_values(service_class._request_class, values))
        except service_form.FormError as error:
            raise BridgeError(str(error)) from None
        reply = self.ros.call(service, service_class, request, timeout_s=self.ros.service_timeout_s)
        return service_form.response_text(reply)
