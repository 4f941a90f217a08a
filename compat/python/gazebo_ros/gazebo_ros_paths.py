"""GazeboRosPaths.get_paths(): the model, plugin and media paths gazebo_ros would export.

gazelle resolves ``model://`` and ``package://`` through the ament index and GAZEBO_MODEL_PATH
itself; this gives launch files the same three strings gazebo_ros does: every installed package's
share folder's parent (model), its lib folder (plugin) and share folder (media), appended to what the
environment already has.
"""

from __future__ import annotations

import os


class GazeboRosPaths:
    @staticmethod
    def get_paths() -> tuple[str, str, str]:
        from ament_index_python.packages import get_packages_with_prefixes

        model, plugin, media = [], [], []
        for name, prefix in sorted(get_packages_with_prefixes().items()):
            share = os.path.join(prefix, "share")
            if os.path.isdir(os.path.join(share, name, "models")) or os.path.isdir(os.path.join(share, name)):
                model.append(share)
            plugin.append(os.path.join(prefix, "lib"))
            media.append(share)

        def join(existing: str, extra: list[str]) -> str:
            parts = [p for p in existing.split(os.pathsep) if p]
            for p in extra:
                if p not in parts:
                    parts.append(p)
            return os.pathsep.join(parts)

        return (
            join(os.environ.get("GAZEBO_MODEL_PATH", ""), model),
            join(os.environ.get("GAZEBO_PLUGIN_PATH", ""), plugin),
            join(os.environ.get("GAZEBO_RESOURCE_PATH", ""), media),
        )
