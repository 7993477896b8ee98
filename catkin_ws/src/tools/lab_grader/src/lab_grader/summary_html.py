"""The class summary page: the score distribution as a histogram (PNG embedded), the most failed checks, and a
table of students linking to their own reports. Self-contained HTML; every submitted text escaped. No ROS import."""
import base64
import html
import io

import matplotlib

matplotlib.use("Agg")
from matplotlib import pyplot  # noqa: E402  (after choosing the backend)

from lab_grader.html_report import STYLE  # noqa: E402

SUMMARY_PAGE = "summary.html"


def score_histogram_png(scores, max_score) -> bytes:
    figure, axes = pyplot.subplots(figsize=(6.4, 3.2), dpi=100)
    try:
        bins = max(1, min(20, int(max_score) or 1))
        axes.hist(scores, bins=bins, range=(0, max_score or 1), color="#1f4ea3", edgecolor="white")
        axes.set_xlabel("score (of {:g})".format(max_score))
        axes.set_ylabel("students")
        axes.set_title("Score distribution ({} students)".format(len(scores)), fontsize=10)
        buffer = io.BytesIO()
        figure.savefig(buffer, format="png", bbox_inches="tight")
        return buffer.getvalue()
    finally:
        pyplot.close(figure)


def summary_html(results, summary) -> str:
    esc = html.escape
    png = base64.b64encode(score_histogram_png([r["score"] for r in results], summary["max_score"])).decode()
    failed = "".join("<tr><td>{}</td><td>{}</td></tr>".format(esc(check_id), count)
                     for check_id, count in summary["most_failed"])
    students = "".join(
        "<tr><td><a href='{id}/report.html'>{id}</a></td><td>{score:g} / {max:g}</td><td>{problem}</td></tr>".format(
            id=esc(r["student"]), score=r["score"], max=r["max_score"],
            problem=esc(r["problems"][0]) if r["problems"] else "")
        for r in results)
    return """<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Class summary</title>
<style>{style}</style></head><body><h1>Class summary: {count} students</h1>
<img id="histogram" alt="score distribution" src="data:image/png;base64,{png}">
<h2>Most failed checks</h2><table id="most-failed"><tr><th>check</th><th>students not passing</th></tr>{failed}</table>
<h2>Students</h2><table id="students"><tr><th>student</th><th>score</th><th>first problem</th></tr>{students}</table>
</body></html>
""".format(style=STYLE, count=len(results), png=png, failed=failed, students=students)
