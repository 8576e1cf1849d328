#!/usr/bin/python3
"""LinuxCNC's DISPLAY for a run without a screen (scripts/linuxcnc/sil.sh):
LinuxCNC starts it as `headless.py -ini INI`; it takes the machine out of
e-stop, turns it on, homes every joint, runs the program of [SIL]PROGRAM
to its end and exits, which shuts LinuxCNC down. Meanwhile halsampler
records the sampler of [SIL]SAMPLES (one line a servo period).

[SIL]FAULT makes the run end otherwise, for the fault tests:
  estop AFTER_S      e-stop pressed AFTER_S seconds into the program
  kill AFTER_S       this process and LinuxCNC's realtime killed (SIGKILL)
  cut AFTER_S,D      the link cut for D seconds (udp_relay.py, told through
                     [SIL]RELAY_CUT); the driver faults the joints; then the
                     machine is turned on again (the driver refuses the first
                     time when LinuxCNC is not where the board stopped), and
                     an MDI move runs from the board's true position
  (none)             the program to its end

Writes [SIL]RESULT (JSON): the program, LinuxCNC's machining time (from
AUTO_RUN to the interpreter idle and the motion done), the errors LinuxCNC
reported, how the run ended. Runs under Debian's python3 (LinuxCNC's
`linuxcnc` module), not the project's environment.
"""
import json
import os
import signal
import subprocess
import sys
import time

import linuxcnc


def wait(what, cond, timeout, stat, errors, err):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        stat.poll()
        drain(err, errors)
        if cond(stat):
            return True
        time.sleep(0.01)
    raise SystemExit(f"headless: timed out waiting for {what} ({timeout} s); errors: {errors}")


def drain(err, errors):
    while True:
        e = err.poll()
        if not e:
            return
        errors.append(e[1])


def driver_pins():
    """The HAL component's pins (hwinterp.*) as `halcmd getp` reads them."""
    out = subprocess.run(["halcmd", "-s", "show", "pin", "hwinterp"], capture_output=True,
                         text=True).stdout
    pins = {}
    for line in out.splitlines():
        f = line.split()
        if len(f) >= 5 and f[4].startswith("hwinterp."):
            v = f[3]
            try:
                pins[f[4]] = float(v) if "." in v or "e" in v else int(v, 0)
            except ValueError:
                pins[f[4]] = {"TRUE": True, "FALSE": False}.get(v, v)
    return pins


def main():
    ini_path = sys.argv[sys.argv.index("-ini") + 1]
    ini = linuxcnc.ini(ini_path)
    program = ini.find("SIL", "PROGRAM")
    result_path = ini.find("SIL", "RESULT")
    samples_path = ini.find("SIL", "SAMPLES")
    fault = (ini.find("SIL", "FAULT") or "").split()
    joints = int(ini.find("KINS", "JOINTS"))
    timeout = float(ini.find("SIL", "TIMEOUT") or 600)

    stat, cmd, err = linuxcnc.stat(), linuxcnc.command(), linuxcnc.error_channel()
    errors = []
    result = {"program": program, "fault": " ".join(fault), "errors": errors}

    def write():
        with open(result_path + ".tmp", "w") as f:
            json.dump(result, f, indent=2)
        os.replace(result_path + ".tmp", result_path)

    sampler = subprocess.Popen(["halsampler", "-t"], stdout=open(samples_path, "w"))
    try:
        wait("the task", lambda s: s.task_state in (linuxcnc.STATE_ESTOP, linuxcnc.STATE_ESTOP_RESET,
                                                    linuxcnc.STATE_OFF, linuxcnc.STATE_ON), 30,
             stat, errors, err)
        cmd.state(linuxcnc.STATE_ESTOP_RESET)
        wait("e-stop reset", lambda s: s.task_state == linuxcnc.STATE_ESTOP_RESET, 10, stat, errors, err)
        cmd.state(linuxcnc.STATE_ON)
        wait("machine on", lambda s: s.task_state == linuxcnc.STATE_ON, 10, stat, errors, err)
        cmd.mode(linuxcnc.MODE_MANUAL)
        cmd.wait_complete()
        cmd.teleop_enable(0)
        cmd.wait_complete()
        cmd.home(-1)
        wait("homing", lambda s: all(s.homed[:joints]), 30, stat, errors, err)
        cmd.teleop_enable(1)
        cmd.wait_complete()
        cmd.mode(linuxcnc.MODE_AUTO)
        cmd.wait_complete()
        cmd.program_open(program)
        cmd.wait_complete()
        cmd.set_optional_stop(0)  # M1 does not stop; M0 (a program stop) is resumed below
        start = time.monotonic()
        cmd.auto(linuxcnc.AUTO_RUN, 0)
        result["started"] = True
        write()
        if fault and fault[0] == "cut":
            after, length = map(float, fault[1].split(","))
            time.sleep(after)
            with open(ini.find("SIL", "RELAY_CUT"), "w") as f:
                f.write(str(length))
            cut = time.monotonic()
            wait("the joints' fault", lambda s: s.task_state != linuxcnc.STATE_ON, length + 5,
                 stat, errors, err)
            result["fault_seen_s"] = time.monotonic() - cut
            stat.poll()
            result["position_at_fault"] = list(stat.joint_actual_position[:joints])
            time.sleep(max(0.0, length + 0.5 - (time.monotonic() - cut)))
            # On again: the driver refuses once when LinuxCNC's position is not
            # the board's (it then reports the board's, which LinuxCNC takes).
            attempts = 0
            for attempts in range(1, 5):
                cmd.state(linuxcnc.STATE_ESTOP_RESET)
                cmd.wait_complete()
                cmd.state(linuxcnc.STATE_ON)
                cmd.wait_complete()
                time.sleep(0.3)
                stat.poll()
                if stat.task_state == linuxcnc.STATE_ON:
                    break
            result["on_attempts"] = attempts
            stat.poll()
            result["position_at_restart"] = list(stat.joint_actual_position[:joints])
            cmd.mode(linuxcnc.MODE_MDI)
            cmd.wait_complete()
            cmd.mdi("G91 G1 X2 Y-2 F600")
            cmd.wait_complete()
            wait("the MDI move", lambda s: s.interp_state == linuxcnc.INTERP_IDLE and
                 s.exec_state == linuxcnc.EXEC_DONE and s.queue == 0, 30, stat, errors, err)
            time.sleep(0.2)
            stat.poll()
            result["position"] = list(stat.joint_actual_position[:joints])
            result["driver"] = driver_pins()
            result["ended"] = "restarted"
            cmd.state(linuxcnc.STATE_OFF)
            time.sleep(0.1)
            return
        if fault:
            kind, after = fault[0], float(fault[1])
            time.sleep(after)
            stat.poll()
            result["position_at_fault"] = list(stat.joint_actual_position[:joints])
            if kind == "estop":
                cmd.state(linuxcnc.STATE_ESTOP)
                result["ended"] = "estop"
                time.sleep(0.5)
            elif kind == "kill":
                result["ended"] = "killed"
                write()
                sampler.terminate()
                # LinuxCNC's realtime and task die at once: nothing stops the board but its watchdog.
                subprocess.run(["pkill", "-KILL", "-f", "rtapi_app"])
                subprocess.run(["pkill", "-KILL", "-f", "milltask"])
                os.kill(os.getpid(), signal.SIGKILL)
            write()
            return
        wait("the program to run", lambda s: s.interp_state != linuxcnc.INTERP_IDLE or
             s.exec_state == linuxcnc.EXEC_DONE, 10, stat, errors, err)
        resumed = []

        def ended(s):
            if s.paused:  # M0: the operator's resume
                resumed.append(time.monotonic())
                cmd.auto(linuxcnc.AUTO_RESUME)
                return False
            return (s.interp_state == linuxcnc.INTERP_IDLE and s.exec_state == linuxcnc.EXEC_DONE
                    and s.queue == 0)
        wait("the program's end", ended, timeout, stat, errors, err)
        result["resumed_after_m0"] = bool(resumed)
        result["machining_s"] = time.monotonic() - start
        result["ended"] = "program end"
        stat.poll()
        result["position"] = list(stat.joint_actual_position[:joints])
        # The board's latency: let the last periods' commands run out.
        time.sleep(0.2)
        result["driver"] = driver_pins()
        cmd.state(linuxcnc.STATE_OFF)
        time.sleep(0.1)
    finally:
        drain(err, errors)
        write()
        sampler.terminate()
        sampler.wait()


if __name__ == "__main__":
    main()
