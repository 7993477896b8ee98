"""A submission's report as one self-contained HTML file (styles inline, the trajectory picture embedded as a data
URL): the score, a table of checks with their kinds, verdicts, reasons and evidence, a table of the services as
found, a table of the nodes (which file served each exercise, how it was found, and the traceback of a node that
crashed), and catkin's error lines and the log's end when the build failed. Every text from the submission is
escaped. No ROS import; matplotlib is imported when a picture is first drawn (lab_grader.pictures)."""
import base64
import html
import json

STYLE = """
body { font: 14px/1.4 system-ui, sans-serif; margin: 2em auto; max-width: 1100px; color: #222; }
h1 { font-size: 1.5em; } table { border-collapse: collapse; width: 100%; margin: 1em 0; }
th, td { border-bottom: 1px solid #ddd; padding: 4px 8px; text-align: left; vertical-align: top; }
.pass { color: #176b2c; font-weight: 600; } .fail { color: #b3261e; font-weight: 600; }
.error { color: #8a5300; font-weight: 600; } .interference, .crashed { color: #6a1b9a; font-weight: 600; }
pre { background: #f6f6f4; padding: 8px; overflow: auto; }
details summary { cursor: pointer; color: #1f4ea3; } img { max-width: 100%; border: 1px solid #ddd; }
"""


def _evidence(check):
    evidence = dict(check.get("evidence") or {})
    evidence.pop("trajectory", None)   # drawn in the picture
    return html.escape(json.dumps(evidence, indent=1, sort_keys=True))


def _cell(value):
    return "" if value is None else html.escape(str(value))


def services_table(services) -> str:
    """The services (and actions) as found: the course's name, the type expected, the name and type found, how."""
    rows = "".join("<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>".format(
        _cell(name), _cell(found.get("expected_type")), _cell(found.get("found") or "not found"),
        _cell(found.get("found_by")), _cell(found.get("found_type")), _cell(found.get("note")))
        for name, found in sorted(services.items()))
    return ("<table id='services'><tr><th>course's name</th><th>type expected</th><th>found</th><th>how</th>"
            "<th>type found</th><th>note</th></tr>{}</table>".format(rows))


def nodes_table(nodes) -> str:
    """One row per exercise: the file that served it (and how it was found), whether it ran to the end, the
    problem; a crashed node's traceback below its row."""
    rows = []
    for node in nodes:
        status = "crashed" if node.get("crashed") else ("running" if node.get("running_at_end") else "not running")
        rows.append("<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td class='{}'>{}</td><td>{}</td></tr>".format(
            _cell(node.get("exercise")), _cell(", ".join(node.get("serves") or [])),
            _cell("{} ({})".format(node["file"], node.get("package")) if node.get("file") else "none"),
            _cell(node.get("found_by") or ("tried: " + ", ".join(node.get("tried") or []) if node.get("tried")
                                          else "")),
            "crashed" if node.get("crashed") else "", status, _cell(node.get("problem") or node.get("crash"))))
        if node.get("traceback") or (node.get("crashed") and node.get("log_tail")):
            rows.append("<tr><td colspan='6'><pre class='traceback'>{}</pre></td></tr>".format(
                _cell(node.get("traceback") or node.get("log_tail"))))
    return ("<table id='nodes'><tr><th>exercise</th><th>serves</th><th>file (package)</th><th>found by</th>"
            "<th>at the end</th><th>problem</th></tr>{}</table>".format("".join(rows)))


def report_html(result, worlds) -> str:
    """The report of one submission's `result` (grade.py's result.json content); `worlds` is [(world, the ids of the
    checks graded in it)]: a picture of their trajectories over each world."""
    esc = html.escape
    rows = "".join(
        "<tr><td>{id}</td><td>{title}</td><td>{kind}</td><td>{weight:g}</td><td class='{verdict}'>{verdict}</td>"
        "<td>{reason}<details><summary>evidence</summary><pre>{evidence}</pre></details></td></tr>".format(
            id=esc(check["id"]), title=esc(check.get("title", "")), kind=esc(check.get("kind", "required")),
            weight=check.get("weight", 0), verdict=esc(check["verdict"]), reason=esc(check.get("reason", "")),
            evidence=_evidence(check))
        for check in result["checks"])
    problems = "".join("<li>{}</li>".format(esc(problem)) for problem in result.get("problems", []))
    build = result.get("build") or {}
    build_log = ""
    if build and not build.get("ok"):
        errors = "\n".join(build.get("errors") or []) or "(no error line recognised: see the log's end)"
        build_log = ("<h2>Build errors (catkin_make)</h2><pre id='build-errors'>{}</pre><details><summary>the build "
                     "log's end</summary><pre>{}</pre></details>".format(esc(errors), esc(build.get("log_tail") or "")))
    pictures = []
    from lab_grader.trajectory_picture import trajectory_png  # matplotlib: see lab_grader.pictures
    for world, check_ids in worlds:
        checks = [check for check in result["checks"] if check["id"] in check_ids]
        if any((check.get("evidence") or {}).get("trajectory") for check in checks):
            png = base64.b64encode(trajectory_png(world, checks)).decode()
            pictures.append("<img id='trajectory{}' alt='trajectories in {}' src='data:image/png;base64,{}'>".format(
                "-{}".format(len(pictures) + 1) if pictures else "", esc(world), png))
    picture = "<h2>Trajectories</h2>" + "".join(pictures) if pictures else ""
    return """<!doctype html><html lang="en"><head><meta charset="utf-8"><title>{student}: {suite}</title>
<style>{style}</style></head><body>
<h1>{student}: {score:g} / {max_score:g} points ({suite})</h1>
{problems_block}
<table id="checks"><tr><th>check</th><th>what</th><th>kind</th><th>weight</th><th>verdict</th><th>reason</th></tr>
{rows}</table>
{picture}
<h2>Services</h2>{services}<h2>Nodes</h2>{nodes}
{build_log}
</body></html>
""".format(student=esc(result["student"]), suite=esc(result["suite"]), style=STYLE, score=result["score"],
           max_score=result["max_score"], rows=rows, picture=picture,
           services=services_table(result.get("services", {})), nodes=nodes_table(result.get("nodes", [])),
           build_log=build_log,
           problems_block="<ul class='problems'>{}</ul>".format(problems) if problems else "")
