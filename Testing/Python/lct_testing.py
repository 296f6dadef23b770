"""Helpers shared by the Python tests (not a test itself: CTest runs Test*.py only)."""
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkCommand


class ErrorRecorder:
    """Observer for vtkCommand.ErrorEvent (or another event with a message, such as
    WarningEvent) that keeps the messages (and silences the output)."""

    def __init__(self, obj, event=vtkCommand.ErrorEvent):
        self.messages = []

        # VTK looks for the call data type on the callback itself: use a decorated function.
        @calldata_type(VTK_STRING)
        def on_error(caller, event, message):
            self.messages.append(message)

        self.callback = on_error
        obj.AddObserver(event, on_error)

    @property
    def count(self):
        return len(self.messages)
