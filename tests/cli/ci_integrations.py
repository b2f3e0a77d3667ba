#!/usr/bin/env python3
"""The CI integrations of the repository run as their CI would run them (docs/ci.md):
- action.yml, the GitHub composite action: its step's script with its inputs put in as GitHub does (`${{ inputs.X }}`
  in the step's env, defaults from the action), GITHUB_OUTPUT set: on good example tapes it succeeds and writes a
  SARIF 2.1.0 report; with a bad tape it fails, the SARIF still written, the error as an annotation;
- ci/essikit.gitlab-ci.yml, the GitLab template: the `.essi-check` job's script lines with its variables: the Code
  Quality JSON and the JUnit report written, the job failing on a tape with an error.
Usage: ci_integrations.py ESSI. Needs python3-yaml."""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
failures = 0


def check(ok, what):
    global failures
    print(("ok   - " if ok else "FAIL - ") + what)
    failures += 0 if ok else 1


def run_action(workdir, inputs):
    """The composite action's step, as GitHub runs it: (returncode, stdout, GITHUB_OUTPUT's text)."""
    action = yaml.safe_load(open(os.path.join(ROOT, "action.yml")))
    values = {k: str(v.get("default", "")) for k, v in action["inputs"].items()}
    values.update(inputs)
    step = action["runs"]["steps"][0]
    env = dict(os.environ)
    for k, v in step["env"].items():
        env[k] = re.sub(r"\$\{\{ inputs\.([\w-]+) \}\}", lambda m: values[m.group(1)], v)
    env["GITHUB_OUTPUT"] = os.path.join(workdir, "github_output")
    r = subprocess.run([step["shell"], "-c", step["run"]], cwd=workdir, env=env, capture_output=True, text=True)
    return r.returncode, r.stdout, open(env["GITHUB_OUTPUT"]).read() if os.path.exists(env["GITHUB_OUTPUT"]) else ""


def run_gitlab_job(workdir, variables):
    """The template's .essi-check job: its script lines in order under its variables; the first failing line's code."""
    job = yaml.safe_load(open(os.path.join(ROOT, "ci", "essikit.gitlab-ci.yml")))[".essi-check"]
    env = dict(os.environ)
    env.update({k: str(v) for k, v in job["variables"].items()})
    env.update(variables)
    for line in job["script"]:
        r = subprocess.run(["bash", "-c", line], cwd=workdir, env=env)
        if r.returncode != 0:
            return r.returncode, job
    return 0, job


def main(essi):
    essi = os.path.abspath(essi)
    with tempfile.TemporaryDirectory() as tmp:
        tapes = os.path.join(tmp, "tapes")
        os.makedirs(tapes)
        for name in ("absolute_offset.esi", "crlf.esi", "woyda_eia.eia"):
            shutil.copy(os.path.join(ROOT, "examples", name), tapes)
        # --- the GitHub action ---
        rc, out, outputs = run_action(tmp, {"paths": "tapes", "essi": essi})
        check(rc == 0, f"action: good tapes pass (rc {rc})")
        sarif = json.load(open(os.path.join(tmp, "essi.sarif")))
        check(sarif.get("version") == "2.1.0" and sarif["runs"][0]["tool"]["driver"]["name"] == "essi",
              "action: a SARIF 2.1.0 report of essi in essi.sarif")
        check("report=essi.sarif" in outputs, "action: the output `report` names it")
        shutil.copy(os.path.join(ROOT, "examples", "bad_arc_off_circle.esi"), tapes)
        rc, out, _ = run_action(tmp, {"paths": "tapes", "essi": essi})
        check(rc == 1, f"action: a bad tape fails the step (rc {rc})")
        results = json.load(open(os.path.join(tmp, "essi.sarif")))["runs"][0]["results"]
        check(any(r["ruleId"] == "E301" for r in results), "action: the SARIF holds the error")
        check(re.search(r"^::error file=tapes/bad_arc_off_circle\.esi,line=\d+", out, re.M) is not None,
              "action: the error is an annotation")
        rc, _, _ = run_action(tmp, {"paths": "tapes", "essi": essi, "fail-on": "never", "format": "junit",
                                    "output": "essi.xml"})
        check(rc == 0 and open(os.path.join(tmp, "essi.xml")).read().startswith("<?xml"),
              "action: fail-on never, format junit")
        # --- the GitLab template ---
        rc, job = run_gitlab_job(tmp, {"ESSI": essi, "ESSI_PATHS": "tapes/"})
        check(rc == 1, f"gitlab: the job fails on the bad tape (rc {rc})")
        quality = json.load(open(os.path.join(tmp, "essi-codequality.json")))
        check(any(i["check_name"] == "E301" and i["severity"] == "critical" for i in quality),
              "gitlab: Code Quality holds the error")
        check(open(os.path.join(tmp, "essi-junit.xml")).read().startswith("<?xml"), "gitlab: the JUnit report")
        reports = job["artifacts"]["reports"]
        check(reports == {"junit": "essi-junit.xml", "codequality": "essi-codequality.json"},
              "gitlab: both reports are the job's artifacts")
        os.remove(os.path.join(tapes, "bad_arc_off_circle.esi"))
        rc, _ = run_gitlab_job(tmp, {"ESSI": essi, "ESSI_PATHS": "tapes/"})
        check(rc == 0, f"gitlab: good tapes pass (rc {rc})")
    print(f"{'all passed' if failures == 0 else f'{failures} failed'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
