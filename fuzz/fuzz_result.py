"""A fuzz run's counts as a verification result (reports/SCHEMA.md, "Verification results"), so that the report
lists the inputs tried, the crashes and the hangs as criteria: issue 32 asks for at least 1e6 inputs through the
scene reader and 1e3 through `sph run`, with 0 crashes and 0 hangs."""


def result(test: str, inputs_name: str, inputs: int, required: int, crashes: int, hangs: int, counts: dict) -> dict:
    source = "issue 32: every input ends in a named exit, never a crash or a hang"
    checks = [
        {"name": "crashes", "measured": crashes, "threshold": 0, "comparison": "==", "source": source,
         "pass": crashes == 0},
        {"name": "hangs", "measured": hangs, "threshold": 0, "comparison": "==", "source": source, "pass": hangs == 0},
    ]
    if required:
        checks.append({"name": inputs_name, "measured": inputs, "threshold": required, "comparison": ">=",
                       "source": f"issue 32: at least {required:g}", "pass": inputs >= required})
    return {"test": test, "issue": 32, "checks": checks,
            "figures": [{"name": inputs_name, "measured": inputs, "source": "counted by the driver"}],
            "counts": counts}
