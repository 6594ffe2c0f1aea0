// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core, module rigidMotion: large rotations
// (rotationInterpolation): the best-fit rigid motion of a body's points
// (RigidFit), the ring between a body and the walls (StarEnvelope), the blend
// weights of several bodies (BodyBlend) and their rigid motions blended into
// the volume (BlendedRigidMotion).
#pragma once

#include "RigidFit.hpp"
#include "StarEnvelope.hpp"
#include "BodyBlend.hpp"
#include "BlendedRigidMotion.hpp"
