"""A rospy service that fails calls the way roscpp does (imports rospy).

roscpp answers a failed call with ok-byte 0 and the raw error text: an empty text when the
callback returns false, the exception's what() when it throws. A rospy client then raises
ServiceException('service [/spawn] responded with an error: b\'\''). A plain rospy.Service
cannot send that: it prefixes its own words ('service cannot process request: ...').

A client that connects and hangs up before sending its request (`rosservice call` with arguments of the wrong
type does) makes roscpp log nothing; rospy.Service logs an ERROR 'incoming connection failed'. This service
logs that at DEBUG level only.
"""
import rospy


class ServiceFailure(Exception):
    """Raised by a RoscppStyleService handler to fail the call; `text` goes to the client as
    is ('' for the original's `return false`)."""

    def __init__(self, text=''):
        super().__init__(text)
        self.text = text


class _Outcome:
    """What the user's handler did with one request: its response, or the exception it raised
    (other than ServiceFailure), handed on to rospy's own sender and error handling."""

    def __init__(self, response=None, error=None):
        self.response = response
        self.error = error


def _unwrap(outcome):
    if outcome.error is not None:
        raise outcome.error
    return outcome.response


class RoscppStyleService(rospy.Service):
    """rospy.Service(name, service_class, handler) whose handler may raise ServiceFailure.

    The handler runs on the connection's thread, once per request, and returns the response
    (anything rospy.Service accepts). ServiceFailure sends ok-byte 0 and its text verbatim.
    Any other exception gets rospy's usual handling (logged, 'error processing request: ...').
    """

    def __init__(self, name, service_class, handler):
        super().__init__(name, service_class, _unwrap)
        self._user_handler = handler

    def _handle_request(self, transport, request):
        try:
            outcome = _Outcome(response=self._user_handler(request))
        except ServiceFailure as failure:
            self._write_service_error(transport, failure.text)
            return
        except Exception as error:  # re-raised inside rospy's sender, which reports it
            outcome = _Outcome(error=error)
        super()._handle_request(transport, outcome)

    def handle(self, transport, header):
        """Serve one connection (rospy.Service.handle) without the ERROR line when the client hangs up."""
        if header.get('probe') == '1':
            transport.close()
            return
        persistent = header.get('persistent', '').lower() in ('1', 'true')
        while True:
            try:
                for request in transport.receive_once():
                    self._handle_request(transport, request)
            except rospy.exceptions.TransportTerminated as error:
                rospy.logdebug('service [%s]: the client closed the connection: %s', self.resolved_name, error)
                break
            if not persistent:
                break
        transport.close()
