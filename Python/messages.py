"""FilterMessages: the error and warning messages of the VTK filters it watches, kept for the
caller to report in its own way instead of printed by VTK."""
from vtkmodules.vtkCommonCore import vtkCommand

__all__ = ["FilterMessages"]


def _text(message, default):
    # VTK's "ERROR: In FILE, line N\nCLASS (0x...): TEXT": the TEXT.
    return str(message).split("): ", 1)[-1].strip() if message else default


class FilterMessages:
    """Watches filters (and readers): their errors go to `messages`, their warnings to
    `warnings`, in the order they came. Use: `messages = FilterMessages();
    reader = messages.watch(vtkSurfaceMeshReader())`, run, then read `messages.messages`."""

    def __init__(self):
        self.messages = []
        self.warnings = []

    def watch(self, algorithm):
        """Records `algorithm`'s errors and warnings; returns it."""
        algorithm.AddObserver(vtkCommand.ErrorEvent, self._record_error)
        algorithm.AddObserver(vtkCommand.WarningEvent, self._record_warning)
        # The executive's "Algorithm ... returned failure" only repeats the filter's message.
        algorithm.GetExecutive().AddObserver(vtkCommand.ErrorEvent, lambda obj, event: None)
        return algorithm

    def _record_error(self, obj, event, message=None):
        self.messages.append(_text(message, "error"))
    _record_error.CallDataType = "string0"

    def _record_warning(self, obj, event, message=None):
        self.warnings.append(_text(message, "warning"))
    _record_warning.CallDataType = "string0"
