"""Plain HTTP checks for tests of web servers (lab_web), without a browser."""
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
