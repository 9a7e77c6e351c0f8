#pragma once
#include "fixture_low/low.h"
