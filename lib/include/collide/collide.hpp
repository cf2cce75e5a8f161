#pragma once
/// @file collide.hpp
/// Umbrella header: shapes, transforms, the registry and every query (overlaps, contact, resolve,
/// distance, bounds, contains, raycast, mass properties), world-space and transformed. The broadphase has its own
/// header, collide/broadphase.hpp.

#include "collide/compound.hpp"
#include "collide/config.hpp"
#include "collide/contains.hpp"
#include "collide/decide.hpp"
#include "collide/error.hpp"
#include "collide/feature.hpp"
#include "collide/mass.hpp"
#include "collide/predicates.hpp"
#include "collide/contact.hpp"
#include "collide/distance.hpp"
#include "collide/overlaps.hpp"
#include "collide/resolve.hpp"
#include "collide/tolerances.hpp"
#include "collide/raycast.hpp"
#include "collide/registry.hpp"
#include "collide/shapes.hpp"
#include "collide/transform.hpp"
#include "collide/transformed.hpp"
#include "collide/cast.hpp"
#include "collide/chain.hpp"
#include "collide/time_of_impact.hpp"
