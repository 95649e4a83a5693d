"""Running mobius-register as a user does and checking what it did: exit code, one-line
messages, outputs left behind. Shared by the application tests."""
import os
import resource
import subprocess
import sys


class Harness:
    """Runs `program` in the folder `work` and collects the failed checks."""

    def __init__(self, program, work):
        self.program = program
        self.work = work
        self.failures = []

    def run(self, *arguments, env=None, cwd=None, timeout=600, memory=None, stack=None):
        """Exit code, standard output and error; a run that hangs is killed and counts as code
        None. `memory`: a limit on the program's address space, `stack` on its stack (that of
        the main thread, and the default of every other), in bytes."""
        def limit():
            if memory:
                resource.setrlimit(resource.RLIMIT_AS, (memory, memory))
            if stack:
                resource.setrlimit(resource.RLIMIT_STACK, (stack, stack))
        try:
            result = subprocess.run([self.program, *arguments], cwd=cwd or self.work, env=env,
                                    capture_output=True, text=True, errors="replace", timeout=timeout,
                                    preexec_fn=limit if memory or stack else None)
        except subprocess.TimeoutExpired:
            return None, "", f"timed out after {timeout} s"
        return result.returncode, result.stdout, result.stderr

    def check(self, condition, message):
        if not condition:
            self.failures.append(message)
            print("FAILED:", message)
        return condition

    def leftovers(self, output):
        """Files in the work folder whose name starts with the output stem `output`."""
        return [f for f in os.listdir(self.work) if f.startswith(output)]

    def check_one_line_error(self, arguments, code, err, words, outputs, code_expected=1):
        """The program failed as it should: exit status, exactly one line of standard error
        holding every one of `words`, never VTK's log format, and no file of `outputs` left."""
        lines = err.strip().splitlines()
        self.check(code == code_expected, f"{arguments}: exit code {code}, expected {code_expected}: {err!r}")
        self.check(len(lines) == 1 and all(w in err for w in words),
                   f"{arguments}: message {err!r} lacks {words}")
        # The program's own line, never VTK's log format (colours, timestamps, file and line).
        self.check("\x1b" not in err and "ERROR: In" not in err and "(0x" not in err,
                   f"{arguments}: VTK's log format in {err!r}")
        for output in outputs:
            left = self.leftovers(output)
            self.check(not left, f"{arguments}: left {left}")

    def expect_failure(self, arguments, words, outputs, env=None, code_expected=1, timeout=600):
        code, _, err = self.run(*arguments, env=env, timeout=timeout)
        self.check_one_line_error(arguments, code, err, words, outputs, code_expected)

    def finish(self):
        print(f"{len(self.failures)} failed")
        sys.exit(1 if self.failures else 0)
