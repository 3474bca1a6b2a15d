"""Scenario files for the small hand-made test models (one actuator, one gripper, one box)."""


def one_actuator_toml(name: str, *, mjcf: str, gripper: str, gripper_geom: str, support: str,
                      actuator: str, limit: float, label: str | None = None, task: bool = False,
                      uncertainty: str, settle: bool = True) -> str:
    """A scenario.toml with the object ``box``/``box``, an explicit one-channel action
    convention and the given ``[uncertainty.*]`` tables (TOML text)."""
    label_line = f'label = "{label}"\n' if label else ""
    task_table = f'[task]\nkind = "pick_hold"\ngripper = "{gripper}"\n'
    return (f'name = "{name}"\n[model]\nmjcf = "{mjcf}"\n[object]\nbody = "box"\ngeom = "box"\n'
            f'settle = {str(settle).lower()}\n'
            f'[grippers.{gripper}]\ngeoms = ["{gripper_geom}"]\n[support]\ngeoms = ["{support}"]\n'
            f'[actions]\nconvention = "explicit"\n[[actions.channel]]\nactuators = ["{actuator}"]\n'
            f'{label_line}{task_table}[limits]\n{actuator} = {limit}\n{uncertainty}')


def soft_copy(scenario, folder):
    """A copy of the bundled scenario's folder under ``folder`` whose scene has MuJoCo's
    default soft friction (pyramidal cone, impratio 1) instead of its elliptic cone with
    impratio 10; returns the copy's folder."""
    import shutil

    shutil.copytree(scenario.path.parent, folder)
    xml = (folder / "scene.xml").read_text()
    assert 'cone="elliptic" impratio="10"' in xml
    (folder / "scene.xml").write_text(xml.replace('cone="elliptic" impratio="10"',
                                                  'cone="pyramidal" impratio="1"'))
    return folder
