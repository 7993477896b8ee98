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


@pytest.mark.parametrize("host_header", ["localhost:8080", "127.0.0.1:8080", "[::1]:8080", "LOCALHOST", "127.0.0.2"])
def test_loopback_hosts_are_allowed(host_header):
    assert AccessPolicy("127.0.0.1").allows_host(host_header)


@pytest.mark.parametrize("host_header", ["evil.example:8080", "evil.example", "localhost.evil.example:8080",
                                         "192.168.1.20:8080", "", None, "[bad:8080", "127.0.0.1@evil.example"])
def test_a_rebinding_name_or_another_address_is_refused_on_loopback(host_header):
    assert not AccessPolicy("127.0.0.1").allows_host(host_header)


def test_the_configured_host_is_allowed():
    policy = AccessPolicy("192.168.1.20", token="class-of-2026")
    assert policy.allows_host("192.168.1.20:8080") and policy.allows_host("localhost:8080")
    assert not policy.allows_host("192.168.1.21:8080") and not policy.allows_host("evil.example:8080")


def test_on_every_interface_any_address_and_the_machine_names_are_allowed():
    policy = AccessPolicy("0.0.0.0", machine_names=("labpc", "labpc.example.org"))
    assert policy.allows_host("10.1.2.3:8080") and policy.allows_host("[fe80::1]:8080")
    assert policy.allows_host("LabPC:8080") and policy.allows_host("labpc.example.org.")
    assert not policy.allows_host("evil.example:8080")
