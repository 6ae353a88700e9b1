#pragma once
// The shape of every bad-input specification: the call throws tv::Error whose message mentions
// each expected string (the argument's name, its value), and the world's state hash does not
// move.

#include <gtest/gtest.h>

#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>

#include "tv/error.hpp"
#include "tv/world.hpp"

template <class F>
void expectRejected(const tv::World& w, std::initializer_list<std::string_view> mentions, F&& f) {
  const std::uint64_t before = w.stateHash();
  try {
    f();
    ADD_FAILURE() << "no tv::Error thrown; expected one mentioning " << *mentions.begin();
  } catch (const tv::Error& e) {
    const std::string msg = e.what();
    for (const std::string_view m : mentions) {
      EXPECT_NE(msg.find(m), std::string::npos) << "message \"" << msg << "\" lacks \"" << m << '"';
    }
  }
  EXPECT_EQ(w.stateHash(), before) << "the failed call changed the world";
}
