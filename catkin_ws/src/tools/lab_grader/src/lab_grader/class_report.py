"""The class's results as files: one CSV row per student (score and every check's verdict), a summary JSON and
the summary page (summary_html.py).
Built from the per-submission result.json files alone, so a single run and the merge of shards give the same
files. No ROS import."""
import csv
import io
import json
from pathlib import Path
from typing import Iterable, List

from lab_grader.grade import RESULT_FILE
from lab_grader.summary_html import SUMMARY_PAGE, summary_html

CSV_FILE = "class.csv"
SUMMARY_FILE = "summary.json"


def read_results(folders: Iterable[Path]) -> List[dict]:
    """Every <folder>/<student>/result.json, sorted by student id; a student found twice is an error (two shards
    that overlap)."""
    results = {}
    for folder in folders:
        for path in sorted(Path(folder).glob("*/" + RESULT_FILE)):
            result = json.loads(path.read_text())
            if result["student"] in results:
                raise ValueError("student {} has results in two places (overlapping shards?): {}".format(
                    result["student"], path))
            results[result["student"]] = result
    return [results[student] for student in sorted(results)]


def check_ids(results: List[dict]) -> List[str]:
    """Check ids in the suite's order, as the first result that ran the checks lists them."""
    for result in results:
        if result["checks"]:
            return [check["id"] for check in result["checks"]]
    return []


def class_csv(results: List[dict]) -> str:
    ids = check_ids(results)
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(["student", "score", "max_score", "percent", "builds"] + ids)
    for result in results:
        verdicts = {check["id"]: check["verdict"] for check in result["checks"]}
        percent = 100.0 * result["score"] / result["max_score"] if result["max_score"] else 0.0
        builds = "" if result["build"] is None else ("yes" if result["build"]["ok"] else "no")
        writer.writerow([result["student"], "{:g}".format(result["score"]), "{:g}".format(result["max_score"]),
                         "{:.1f}".format(percent), builds] + [verdicts.get(check_id, "not run") for check_id in ids])
    return out.getvalue()


def summary(results: List[dict]) -> dict:
    """Scores, and how often each check failed or errored, most failed first."""
    ids = check_ids(results)
    failures = {check_id: 0 for check_id in ids}
    for result in results:
        verdicts = {check["id"]: check["verdict"] for check in result["checks"]}
        for check_id in ids:
            if verdicts.get(check_id) != "pass":
                failures[check_id] += 1
    return {"students": len(results),
            "scores": {result["student"]: result["score"] for result in results},
            "max_score": max((result["max_score"] for result in results), default=0),
            "most_failed": sorted(failures.items(), key=lambda item: (-item[1], ids.index(item[0])))}


def write_class_report(results: List[dict], out_dir: Path) -> None:
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    (out_dir / CSV_FILE).write_text(class_csv(results))
    content = summary(results)
    (out_dir / SUMMARY_FILE).write_text(json.dumps(content, indent=1, sort_keys=True))
    (out_dir / SUMMARY_PAGE).write_text(summary_html(results, content))
