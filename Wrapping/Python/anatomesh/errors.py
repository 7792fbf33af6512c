"""The errors of pipeline files: each names the file and line."""


class PipelineError(Exception):
    """A problem with a pipeline file or its execution; str() names the file and line."""


class UndeclaredVariableError(PipelineError):
    """--set names a variable the pipeline does not declare (a command-line mistake)."""
