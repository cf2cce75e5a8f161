#pragma once
/// @file collide.hpp
/// Umbrella header: shapes, the registry, every query and the broadphase.

#include "collide/compound.hpp"
#include "collide/config.hpp"
#include "collide/decide.hpp"
#include "collide/error.hpp"
#include "collide/predicates.hpp"
#include "collide/queries.hpp"
#include "collide/registry.hpp"
#include "collide/shapes.hpp"
