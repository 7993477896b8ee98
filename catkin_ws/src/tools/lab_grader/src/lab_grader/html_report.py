"""A submission's report as one self-contained HTML file (styles inline, the trajectory picture embedded as a data
URL): the score, a table of checks with their verdicts, reasons and evidence, the services as found, the nodes
started, and the build log when the build failed. Every text from the submission is escaped. No ROS import."""
import base64
import html
import json

from lab_grader.trajectory_picture import trajectory_png

STYLE = """
body { font: 14px/1.4 system-ui, sans-serif; margin: 2em auto; max-width: 1100px; color: #222; }
h1 { font-size: 1.5em; } table { border-collapse: collapse; width: 100%; margin: 1em 0; }
th, td { border-bottom: 1px solid #ddd; padding: 4px 8px; text-align: left; vertical-align: top; }
.pass { color: #176b2c; font-weight: 600; } .fail { color: #b3261e; font-weight: 600; }
.error { color: #8a5300; font-weight: 600; } .interference { color: #6a1b9a; font-weight: 600; }
pre { background: #f6f6f4; padding: 8px; overflow: auto; }
details summary { cursor: pointer; color: #1f4ea3; } img { max-width: 100%; border: 1px solid #ddd; }
"""


def _evidence(check):
    evidence = dict(check.get("evidence") or {})
    evidence.pop("trajectory", None)   # drawn in the picture
    return html.escape(json.dumps(evidence, indent=1, sort_keys=True))


def report_html(result, world_name) -> str:
    """The report of one submission's `result` (grade.py's result.json content)."""
    esc = html.escape
    rows = "".join(
        "<tr><td>{id}</td><td>{title}</td><td>{weight:g}</td><td class='{verdict}'>{verdict}</td><td>{reason}"
        "<details><summary>evidence</summary><pre>{evidence}</pre></details></td></tr>".format(
            id=esc(check["id"]), title=esc(check.get("title", "")), weight=check.get("weight", 0),
            verdict=esc(check["verdict"]), reason=esc(check.get("reason", "")), evidence=_evidence(check))
        for check in result["checks"])
    services = "".join("<li>{}: {}</li>".format(esc(key), esc(json.dumps(value)))
                       for key, value in sorted(result.get("services", {}).items()))
    nodes = "".join("<li>{}</li>".format(esc(json.dumps(node))) for node in result.get("nodes", []))
    problems = "".join("<li>{}</li>".format(esc(problem)) for problem in result.get("problems", []))
    build = result.get("build") or {}
    build_log = ("<h2>Build log (end)</h2><pre>{}</pre>".format(esc(build.get("log_tail") or ""))
                 if build and not build.get("ok") else "")
    picture = ""
    if any((check.get("evidence") or {}).get("trajectory") for check in result["checks"]):
        png = base64.b64encode(trajectory_png(world_name, result["checks"])).decode()
        picture = "<h2>Trajectories</h2><img id='trajectory' alt='trajectories' src='data:image/png;base64,{}'>".format(
            png)
    return """<!doctype html><html lang="en"><head><meta charset="utf-8"><title>{student}: {suite}</title>
<style>{style}</style></head><body>
<h1>{student}: {score:g} / {max_score:g} points ({suite})</h1>
{problems_block}
<table id="checks"><tr><th>check</th><th>what</th><th>weight</th><th>verdict</th><th>reason</th></tr>{rows}</table>
{picture}
<h2>Services</h2><ul>{services}</ul><h2>Nodes</h2><ul>{nodes}</ul>
{build_log}
</body></html>
""".format(student=esc(result["student"]), suite=esc(result["suite"]), style=STYLE, score=result["score"],
           max_score=result["max_score"], rows=rows, picture=picture, services=services, nodes=nodes,
           build_log=build_log,
           problems_block="<ul class='problems'>{}</ul>".format(problems) if problems else "")
