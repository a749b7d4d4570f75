"""Pinocchio's composition of a model Drake's parser read: for SDFormat,
which Pinocchio's pip wheel cannot read (`pin.WITH_SDFORMAT` is false).

Drake parses the file (its libsdformat: worlds, nested models, includes,
frames, `relative_to`); its MultibodyPlant's tree is rebuilt here, joint by
joint, as a Pinocchio model, whose kinematics (`forwardKinematics`), total
mass (`computeTotalMass`), centre of mass (`centerOfMass`) and centroidal
composite inertia (`ccrba`'s `data.Ig`) are then Pinocchio's own. What is
Drake's is only the reading: each joint's frames on its parent and child
(`frame_on_parent`, `frame_on_child`), axis and type, and each body's
spatial inertia in its own frame.

The translation, per Drake joint from parent body P to child body C, with
F its frame on P and M its frame on C (F and M coincide at q = 0):
- revolute, prismatic: Pinocchio's `RevoluteUnaligned`/`PrismaticUnaligned`
  about Drake's axis (expressed in F), placed at F in the parent's joint
  frame; the child body sits at M⁻¹ (X_MC) in the new joint's frame;
- ball (Drake's `BallRpyJoint`, q = roll, pitch, yaw): `Spherical`, its
  quaternion from Drake's rotation;
- floating (Drake's `QuaternionFloatingJoint` for a body no joint holds,
  q = w, x, y, z, position): `FreeFlyer`, so the root counts as the issue
  asks (a free-flyer root at its pose);
- weld: no Pinocchio joint; the child is appended to the parent's joint
  at X_JP·X_PF·X_FM·X_MC. Drake's world is a free flyer at the identity,
  never moved, so that bodies welded to it count (Pinocchio's universe
  carries no mass).
Any other joint type is refused (the caller names the file as skipped).
"""

import numpy as np
import pinocchio as pin


def _se3(x):
    """A Drake RigidTransform as Pinocchio's SE3."""
    return pin.SE3(np.array(x.rotation().matrix()), np.array(x.translation()))


class PinOfDrake:
    def __init__(self, plant, ctx):
        """Pinocchio's model of `plant`'s tree; bodies' inertias read from
        `ctx` (where the caller set any inertial as written)."""
        from pydrake.multibody.tree import BodyIndex, JointIndex

        p = plant
        self.model = pin.Model()
        # Per Drake body index: (Pinocchio joint id, X_JB: the body's frame
        # in that joint's frame). Drake's world is a free flyer at the
        # identity (q stays neutral), so that what is welded to it counts
        # (Pinocchio's universe carries no mass).
        top = self.model.addJoint(0, pin.JointModelFreeFlyer(), pin.SE3.Identity(), "world")
        at = {0: (top, pin.SE3.Identity())}
        # Per Drake joint: (Pinocchio joint id, kind).
        self.joints = []
        pending = [p.get_joint(JointIndex(k)) for k in range(p.num_joints())]
        while pending:
            later = []
            for j in pending:
                parent, child = int(j.parent_body().index()), int(j.child_body().index())
                if parent not in at:
                    later.append(j)
                    continue
                pid, x_jp = at[parent]
                x_pf = _se3(j.frame_on_parent().GetFixedPoseInBodyFrame())
                x_cm = _se3(j.frame_on_child().GetFixedPoseInBodyFrame())
                x_jf = x_jp * x_pf
                kind = j.type_name()
                if kind == "weld":
                    at[child] = (pid, x_jf * _se3(j.X_FM()) * x_cm.inverse())
                    continue
                if kind == "revolute":
                    model = pin.JointModelRevoluteUnaligned(np.array(j.revolute_axis()))
                elif kind == "prismatic":
                    model = pin.JointModelPrismaticUnaligned(np.array(j.translation_axis()))
                elif kind == "ball_rpy":
                    model = pin.JointModelSpherical()
                elif kind == "quaternion_floating":
                    model = pin.JointModelFreeFlyer()
                else:
                    raise ValueError(f"a `{kind}` joint ({j.name()}) has no translation to Pinocchio here")
                jid = self.model.addJoint(pid, model, x_jf, f"{j.name()}#{int(j.index())}")
                self.joints.append((j, jid, kind))
                at[child] = (jid, x_cm.inverse())
            if len(later) == len(pending):
                raise ValueError("a body hangs from no body the world reaches")
            pending = later
        for k in range(1, p.num_bodies()):
            b = p.get_body(BodyIndex(k))
            if k not in at:
                raise ValueError(f"body {b.name()} is held by no joint")
            jid, x_jb = at[k]
            s = b.CalcSpatialInertiaInBodyFrame(ctx)
            m = s.get_mass()
            c = np.array(s.get_com())
            if m > 0:
                # About the body's origin in its frame, shifted by Pinocchio
                # to the centre (`Inertia.FromDynamicParameters`' layout is
                # about the frame origin: m, m·c, I_o).
                i_o = np.array(s.CalcRotationalInertia().CopyToFullMatrix3())
                dyn = np.array([m, *(m * c), i_o[0, 0], i_o[0, 1], i_o[1, 1], i_o[0, 2], i_o[1, 2], i_o[2, 2]])
                self.model.appendBodyToJoint(jid, pin.Inertia.FromDynamicParameters(dyn), x_jb)
        self.data = self.model.createData()

    def body(self, q_drake):
        """Mass, centre of mass and inertia about it (world axes) at Drake's
        position vector `q_drake`, computed by Pinocchio."""
        from pydrake.math import RollPitchYaw

        q = pin.neutral(self.model)
        for j, jid, kind in self.joints:
            i, o = j.position_start(), self.model.joints[jid].idx_q
            if kind in ("revolute", "prismatic"):
                q[o] = q_drake[i]
            elif kind == "ball_rpy":
                r = RollPitchYaw(q_drake[i : i + 3]).ToQuaternion()
                q[o : o + 4] = [r.x(), r.y(), r.z(), r.w()]
            else:  # quaternion_floating: Drake (w, x, y, z, p), Pinocchio (p, x, y, z, w)
                w, x, y, z = q_drake[i : i + 4]
                q[o : o + 7] = [*q_drake[i + 4 : i + 7], x, y, z, w]
        mass = pin.computeTotalMass(self.model, self.data)
        com = pin.centerOfMass(self.model, self.data, q)
        pin.ccrba(self.model, self.data, q, np.zeros(self.model.nv))
        return mass, np.array(com), np.array(self.data.Ig.inertia)
