"""One writer per checkpoint or store, no stale lock after a kill, and pool workers that die
with their parent (`stickslip.files`)."""

import os
import signal
import subprocess
import sys
import textwrap
import time

import pytest

from stickslip.errors import ParameterError
from stickslip.files import exclusive

HOLD = textwrap.dedent("""
    import sys, time
    from stickslip.files import exclusive
    with exclusive(sys.argv[1], "checkpoint"):
        print("locked", flush=True)
        time.sleep(60)
""")


def _holder(path):
    proc = subprocess.Popen([sys.executable, "-c", HOLD, str(path)], stdout=subprocess.PIPE, text=True)
    assert proc.stdout.readline().strip() == "locked"
    return proc


def test_a_second_writer_is_refused_and_a_killed_writer_leaves_no_lock(tmp_path):
    path = tmp_path / "run.nc"
    proc = _holder(path)
    try:
        with pytest.raises(ParameterError) as err:
            with exclusive(path, "checkpoint"):
                pass
        assert err.value.name == "checkpoint" and "another stickslip process" in err.value.allowed
    finally:
        proc.send_signal(signal.SIGKILL)
        proc.wait()
        proc.stdout.close()
    with exclusive(path, "checkpoint"):  # the lock died with its process
        pass
    assert not (tmp_path / "run.nc.lock").exists()


def test_a_second_brake_run_on_one_checkpoint_is_refused(tmp_path):
    from stickslip.brake import BrakeParams
    from stickslip.brake.ring import integrate

    path = tmp_path / "run.nc"
    proc = _holder(path)
    try:
        with pytest.raises(ParameterError) as err:
            integrate(BrakeParams.from_physical(50.0, 1e-4, 0.7), 32, transits=1, checkpoint=path)
        assert err.value.name == "checkpoint"
    finally:
        proc.send_signal(signal.SIGKILL)
        proc.wait()
        proc.stdout.close()


POOL = textwrap.dedent("""
    import multiprocessing, time
    from concurrent.futures import ProcessPoolExecutor
    from stickslip.files import die_with_parent

    def work(_):
        import os, sys
        sys.stdout.write(f"{os.getpid()}\\n")  # one write: two workers' lines cannot interleave
        sys.stdout.flush()
        time.sleep(60)

    if __name__ == "__main__":
        pool = ProcessPoolExecutor(2, mp_context=multiprocessing.get_context("spawn"), initializer=die_with_parent)
        futures = [pool.submit(work, i) for i in range(2)]
        time.sleep(60)
""")


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="PR_SET_PDEATHSIG is Linux's")
def test_pool_workers_die_with_their_parent(tmp_path):
    script = tmp_path / "pool.py"
    script.write_text(POOL)
    parent = subprocess.Popen([sys.executable, str(script)], stdout=subprocess.PIPE, text=True)
    workers = [int(parent.stdout.readline()) for _ in range(2)]
    parent.send_signal(signal.SIGKILL)
    parent.wait()
    parent.stdout.close()
    deadline = time.monotonic() + 20
    alive = workers
    while alive and time.monotonic() < deadline:
        time.sleep(0.1)
        alive = [pid for pid in alive if _alive(pid)]
    assert not alive


def _alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    try:  # a zombie (dead, not yet reaped by init) counts as dead
        with open(f"/proc/{pid}/stat") as f:
            return f.read().split(")")[-1].split()[0] != "Z"
    except OSError:
        return False


def test_a_netcdf_write_does_not_import_distributed_and_reads_back(tmp_path):
    """`files.to_netcdf` skips xarray's cluster probe (an import of `distributed`, 0.3-0.7 s)
    when the process has none, writes the same file, and leaves `distributed` importable."""
    code = textwrap.dedent(f"""
        import sys
        import numpy as np, xarray as xr
        from stickslip.files import to_netcdf
        ds = xr.Dataset({{"a": ("x", np.arange(3.0))}})
        to_netcdf(ds, {str(tmp_path / 'a.nc')!r})
        print("distributed" in sys.modules, "dask.distributed" in sys.modules)
        import distributed  # still importable after the write
        to_netcdf(ds, {str(tmp_path / 'b.nc')!r})  # and a write with it imported
        assert xr.load_dataset({str(tmp_path / 'a.nc')!r}).identical(xr.load_dataset({str(tmp_path / 'b.nc')!r}))
        assert xr.load_dataset({str(tmp_path / 'a.nc')!r})["a"].values.tolist() == [0.0, 1.0, 2.0]
        """)
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["False", "False"]
