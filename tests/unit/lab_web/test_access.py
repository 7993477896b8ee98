"""Who may open the page: anyone on this machine by default; a token once the page listens beyond loopback."""
import pytest

from lab_web.access import AccessError, AccessPolicy


@pytest.mark.parametrize("host", ["127.0.0.1", "localhost", "::1", "127.0.1.1"])
def test_loopback_needs_no_token(host):
    policy = AccessPolicy(host)
    assert policy.token is None and policy.allows(None) and policy.warning() is None


def test_any_other_address_needs_a_random_token_and_warns():
    policy = AccessPolicy("0.0.0.0")
    assert len(policy.token) >= 16
    assert not policy.allows(None) and not policy.allows("") and not policy.allows(policy.token[:-1])
    assert policy.allows(policy.token)
    assert policy.url(8080) == "http://localhost:8080/?token=" + policy.token
    assert "drive the robot" in policy.warning()
    assert AccessPolicy("0.0.0.0").token != policy.token


def test_a_given_token_is_used():
    policy = AccessPolicy("192.168.1.20", token="class-of-2026")
    assert policy.allows("class-of-2026") and policy.url(9000) == "http://192.168.1.20:9000/?token=class-of-2026"


@pytest.mark.parametrize("host, token, reason", [("", "", "host"), ("0.0.0.0", "short", "at least 8")])
def test_unusable_settings_are_refused(host, token, reason):
    with pytest.raises(AccessError, match=reason):
        AccessPolicy(host, token)
