"""Concurrency: many clients calling simulation_interfaces at once all get correct answers; no request is lost."""

from __future__ import annotations

import threading
from concurrent.futures import ThreadPoolExecutor

import pytest
from _harness import RosClient
from geometry_msgs.msg import PoseStamped
from simulation_interfaces.msg import Result
from simulation_interfaces.srv import DeleteEntity, GetEntities, GetEntityState, SpawnEntity

pytestmark = [pytest.mark.ros, pytest.mark.serial]  # load tests: run alone (./test.sh)

NS = "/gazelle/"
THREADS, ROUNDS = 8, 25  # 8 clients x 25 rounds x 4 calls = 800 calls
BOX = (
    '<?xml version="1.0"?><sdf version="1.9"><model name="box"><link name="link"><inertial><mass>0.5</mass></inertial>'
    '<collision name="c"><geometry><box><size>0.1 0.1 0.1</size></box></geometry></collision></link></model></sdf>'
)


def test_many_clients_at_once(sim_factory) -> None:
    sim_factory()
    clients = [RosClient(f"conc_client_{i}") for i in range(THREADS)]
    answered = [0] * THREADS
    errors: list[str] = []
    barrier = threading.Barrier(THREADS)

    def worker(k: int) -> None:
        ros = clients[k]
        barrier.wait()
        for r in range(ROUNDS):
            name = f"c{k}_box_{r}"
            pose = PoseStamped()
            pose.pose.position.x, pose.pose.position.y, pose.pose.position.z = float(k), float(r) * 0.3, 0.05
            res = ros.call(
                SpawnEntity,
                NS + "spawn_entity",
                SpawnEntity.Request(name=name, resource_string=BOX, initial_pose=pose),
                timeout=30,
            )
            if res.result.result != Result.RESULT_OK or res.entity_name != name:
                errors.append(f"spawn {name}: {res.result.error_message}")
            answered[k] += 1
            st = ros.call(GetEntityState, NS + "get_entity_state", GetEntityState.Request(entity=name), timeout=30)
            p = st.state.pose.position
            if st.result.result != Result.RESULT_OK or abs(p.x - k) > 0.01 or abs(p.y - r * 0.3) > 0.01:
                errors.append(f"state {name}: {st.result.error_message} at ({p.x:.3f}, {p.y:.3f})")
            answered[k] += 1
            ents = ros.call(GetEntities, NS + "get_entities", GetEntities.Request(), timeout=30)
            if ents.result.result != Result.RESULT_OK or name not in ents.entities:
                errors.append(f"get_entities misses {name}")
            answered[k] += 1
            d = ros.call(DeleteEntity, NS + "delete_entity", DeleteEntity.Request(entity=name), timeout=30)
            if d.result.result != Result.RESULT_OK:
                errors.append(f"delete {name}: {d.result.error_message}")
            answered[k] += 1

    try:
        with ThreadPoolExecutor(THREADS) as pool:
            for f in [pool.submit(worker, k) for k in range(THREADS)]:
                f.result()
        left = clients[0].call(GetEntities, NS + "get_entities", GetEntities.Request())
    finally:
        for c in clients:
            c.close()
    assert not errors, "\n".join(errors[:20])
    assert answered == [4 * ROUNDS] * THREADS  # every request answered
    assert not [e for e in left.entities if "_box_" in e]  # every delete took effect
