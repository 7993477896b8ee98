"""Exceptions of the simulation core, all under one root so the ROS layer translates them in one place.

The ROS node maps these onto the Gazebo-style service responses (spec §5), for example
`DuplicateModelError` -> "SpawnModel: Failure - entity already exists." and `UnknownModelError` ->
"DeleteModel: model does not exist". The messages here are for humans and logs; the class says what happened.
"""


class SimError(Exception):
    """Root of every error raised by the tb3_sim core."""


class WorldFileError(SimError):
    """A world file is missing, unparsable, or has an unknown key or a bad value.

    `path` is the file and `key` the dotted location inside it (e.g. ``models[2].size``); both are also in
    the message so a log line alone says what to fix.
    """

    def __init__(self, path, key, problem):
        self.path = str(path)
        self.key = key
        self.problem = problem
        super().__init__(f"{self.path}: {key}: {problem}")


class DuplicateModelError(SimError):
    """A model with this name already exists (Gazebo: "entity already exists")."""


class UnknownModelError(SimError):
    """No model has this name."""


class OverlapError(SimError):
    """A model would be created inside the robot or another model."""


class ProtectedModelError(SimError):
    """The operation is refused for this model (the robot, the ground plane, the static world geometry)."""


class InvalidCommandError(SimError):
    """A velocity command is not a finite number or is beyond the sanity limits."""


class ConfigError(SimError):
    """A node parameter has a bad type or value, or names a world that does not exist."""


class ModelXmlError(SimError):
    """A spawn request's SDF or URDF cannot be turned into a model (syntax, format or unsupported content)."""


class NotModelXmlError(ModelXmlError):
    """The text is not XML, or its root is neither SDF (<sdf>/<gazebo>) nor URDF (<robot>)."""


class NotUrdfError(ModelXmlError):
    """spawn_urdf_model was given something other than URDF."""


class UnknownFrameError(SimError):
    """A reference frame names no model (and is not "", "world", "map" or "/map")."""


class BadRequestError(SimError):
    """A service request holds NaN, inf or an otherwise unusable value."""


class ModelLimitError(SimError):
    """The world already holds world.MAX_MODELS models: another spawn is refused."""
