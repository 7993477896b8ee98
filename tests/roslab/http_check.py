"""Plain HTTP checks for tests of web servers (lab_web), without a browser. (Not named http.py: scripts in this
folder, such as client_loop.py, would then import it instead of the standard library's http package.)"""
import urllib.error
import urllib.request


def http_status(url, timeout_s=2.0):
    """The HTTP status of GET `url`, or None while nothing answers."""
    try:
        with urllib.request.urlopen(url, timeout=timeout_s) as response:
            return response.status
    except urllib.error.HTTPError as error:
        return error.code
    except OSError:
        return None
