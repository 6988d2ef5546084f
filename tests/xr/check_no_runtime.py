#!/usr/bin/env python3
"""kumite play --xr with no OpenXR runtime (XR_RUNTIME_JSON names a missing manifest): exit 1, a message that names
OpenXR, what the loader looked at and how to get a runtime; no report written, no crash, no hang."""
import os
import subprocess
import sys
import tempfile

kumite, database = sys.argv[1], sys.argv[2]
with tempfile.TemporaryDirectory() as folder:
    report = os.path.join(folder, "report.json")
    run = subprocess.run([kumite, "play", database, "--xr", "--duration", "2", "--report", report],
                         capture_output=True, text=True, timeout=60)
    message = [line for line in run.stderr.splitlines() if line.startswith("kumite play --xr:")]
    print(run.returncode, message)
    assert run.returncode == 1, f"exit status {run.returncode}, not 1"
    assert message, "no 'kumite play --xr:' message on stderr:\n" + run.stderr
    text = message[0]
    for needed in ("OpenXR runtime", os.environ["XR_RUNTIME_JSON"], "Monado", "scripts/build_monado.sh"):
        assert needed in text, f"the message does not say {needed!r}: {text}"
    assert not os.path.exists(report), "a report was written for a bout that never started"
print("no runtime: exit 1 with a message naming OpenXR, the manifest looked for and how to install one")
