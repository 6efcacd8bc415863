import json, os, subprocess, sys  # an outside implementation for `lpvid oracle`: here it asks lpvid itself
data, model, task_path, out = sys.argv[1:5]
task = json.load(open(task_path))
bounds = {"min_dmax": ["--delta", task.get("delta")], "min_delta": ["--dmax", task.get("dmax")], "weighted": ["--lambda", task.get("lambda")],
          "decide": ["--delta", task.get("delta"), "--dmax", task.get("dmax")]}[task["kind"]]
cmd = [os.environ.get("LPVID", "lpvid"), "invalidate", "--quiet", "--data", data, "--model", model, "--report", out + ".report.json"]
code = subprocess.run(cmd + ["--certificate", out + ".cert.json"] + bounds, stdout=subprocess.DEVNULL).returncode
report = json.load(open(out + ".report.json"))
answer = {"delta": report["delta"], "dmax": report["dmax"], "verdict": "invalidated" if code == 1 else "consistent"}
json.dump(dict({k: v for k, v in answer.items() if v is not None}, format="lpvid-oracle-answer/1"), open(out, "w"))
