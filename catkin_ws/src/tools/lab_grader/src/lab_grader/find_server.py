"""`python3 -m lab_grader.find_server --timeout S [--any] KIND:NAME:TYPE ...`: wait until the master offers the
exercise's services and actions, found as the checks find them (lab_grader.checks.context): a service by the
course's name or by any name whose server declares the expected type's md5sum; an action by the course's
namespace or any namespace whose <ns>/result topic has an ActionResult type of the same name. KIND is `service` or
`action`. Prints {"found": {NAME: the name found, ...}} as JSON and exits 0 once every one is found (with --any: one
of them), 1 after S wall seconds without, or (with --give-up S2) S2 wall seconds after a new node came up (its
<node>/get_loggers service, which rospy registers at init_node) without offering any: a script that is not the
exercise's server is let go as soon as it is seen running, however long a loaded machine took to start it.
The grader runs it beside one student script at a time to learn which of a submission's scripts serves an
exercise. No node is registered (it only asks the master and the servers' TCPROS headers, as `rosservice type`
does)."""
import argparse
import json
import sys
import time

import rosgraph
import roslib.message
import rosservice

POLL_S = 0.2
CALLER_ID = "/lab_grader_find_server"
GRADER_NODE_PREFIX = "/lab_grader_"   # the grader's own nodes (its check runner, /lab_grader_checks_<pid>_...):
                                      # one coming up is not the tried script's


def service_md5(type_name):
    service_class = roslib.message.get_service_class(type_name)
    if service_class is None:
        raise ValueError("cannot load service type {}: is its package built?".format(type_name))
    return service_class._md5sum


def offered_services(master, headers):
    """{service name: md5sum} of every service on the master whose server answers a header probe (cached per URI)."""
    offered = {}
    for name, _providers in master.getSystemState()[2]:
        try:
            uri = master.lookupService(name)
        except (rosgraph.MasterError, OSError):
            continue
        if (name, uri) not in headers:
            try:
                headers[(name, uri)] = rosservice.get_service_headers(name, uri).get("md5sum")
            except Exception:  # noqa: BLE001 - unreachable, dead, or a malformed header: look again next time
                continue
        offered[name] = headers[(name, uri)]
    return offered


def offered_actions(master):
    """{action namespace: action type name without package} of every <ns>/result topic of an ActionResult type."""
    return {name[:-len("/result")]: topic_type[:-len("ActionResult")].split("/")[-1]
            for name, topic_type in master.getPublishedTopics("")
            if name.endswith("/result") and topic_type.endswith("ActionResult")}


def running_nodes(master):
    """The nodes on the master that rospy has initialised (each offers <node>/get_loggers), but the grader's."""
    return {name[:-len("/get_loggers")] for name, _ in master.getSystemState()[2]
            if name.endswith("/get_loggers") and not name.startswith(GRADER_NODE_PREFIX)}


def find(specs, master, headers):
    """{spec name: the name that serves it} for the specs (kind, name, type) offered now."""
    services = offered_services(master, headers) if any(kind == "service" for kind, _, _ in specs) else {}
    actions = offered_actions(master) if any(kind == "action" for kind, _, _ in specs) else {}
    found = {}
    for kind, name, type_name in specs:
        if kind == "service":
            md5 = service_md5(type_name)
            matches = [name] if services.get(name) == md5 else sorted(n for n, m in services.items() if m == md5)
        else:
            wanted = type_name.split("/")[-1]
            matches = [name] if actions.get(name) == wanted else sorted(n for n, t in actions.items() if t == wanted)
        if matches:
            found[name] = matches[0]
    return found


def parse_spec(text):
    parts = text.split(":")
    if len(parts) != 3 or parts[0] not in ("service", "action"):
        raise argparse.ArgumentTypeError("expected service:/name:pkg/Type or action:/ns:pkg/Name, got {!r}".format(
            text))
    return tuple(parts)


def main(argv=None):
    parser = argparse.ArgumentParser(prog="find_server", description=__doc__.split("\n\n")[0])
    parser.add_argument("--timeout", type=float, required=True, help="wall seconds to wait")
    parser.add_argument("--any", action="store_true", help="succeed once any one of them is found")
    parser.add_argument("--give-up", type=float, default=None, metavar="S2",
                        help="fail S2 wall seconds after a new node has come up without offering them")
    parser.add_argument("specs", nargs="+", type=parse_spec, metavar="KIND:NAME:TYPE")
    args = parser.parse_args(argv)
    master = rosgraph.Master(CALLER_ID)
    headers = {}
    deadline = time.monotonic() + args.timeout
    found = {}
    nodes_before = None
    while True:
        try:
            found = find(args.specs, master, headers)
            nodes = running_nodes(master)
        except (rosgraph.MasterError, OSError):
            found, nodes = {}, nodes_before or set()
        if nodes_before is None:
            nodes_before = nodes
        if (found and args.any) or len(found) == len(args.specs) or time.monotonic() > deadline:
            break
        if args.give_up is not None and nodes - nodes_before:
            deadline = min(deadline, time.monotonic() + args.give_up)
            nodes_before = nodes
        time.sleep(POLL_S)
    print(json.dumps({"found": found}), flush=True)
    return 0 if found and (args.any or len(found) == len(args.specs)) else 1


if __name__ == "__main__":
    sys.exit(main())
