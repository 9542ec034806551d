#include <algorithm>
#include <antkit/kernel/raster.hpp>
#include <antkit/los/fast_wall_follow.hpp>
#include <cstdlib>

namespace antkit::los {

using kernel::Cell;

namespace {

constexpr int mod8(int k) noexcept {
  return ((k % 8) + 8) % 8;
}
Cell offset(int k) noexcept {
  return kernel::kNeighbours8[static_cast<std::size_t>(mod8(k))];
}
std::int32_t chebyshev(Cell a, Cell b) {
  return std::max(std::abs(a.x - b.x), std::abs(a.y - b.y));
}

} // namespace

int trace_step(const ExplorationMap& map, const WallTracer& t, WallTracer& next) {
  if (t.wall < 0) return -1;
  // Left hand: rotate clockwise (decreasing index) away from the wall; right hand: the mirror.
  const int s = t.hand == Hand::Left ? -1 : 1;
  for (int i = 1; i < 8; ++i) {
    const int k = mod8(t.wall + s * i);
    const Cell to = t.position + offset(k);
    if (!map.known_free(to)) continue;
    // The neighbour checked just before k was blocked (or k - s is the wall itself); it becomes
    // the wall seen from the new cell. The two are consecutive on the ring around t.position, so
    // they are neighbours.
    const Cell wall = t.position + offset(k - s);
    next = {to, static_cast<std::int8_t>(direction_of(wall - to)), t.hand};
    return k;
  }
  return -1;
}

int initial_wall(const ExplorationMap& map, Cell at, Hand hand) {
  const int s = hand == Hand::Left ? -1 : 1;
  for (int k = 0; k < 8; ++k)
    if (!map.known_free(at + offset(k)) && map.known_free(at + offset(k + s))) return k;
  return -1;
}

FastWallFollow::FastWallFollow(std::int32_t width, std::int32_t height,
                               FastWallFollowOptions options)
    : width_(width), height_(height), map_(width, height),
      completion_(width, height, options.weights), lost_mark_(width, height, 0),
      visited_(width, height, 0),
      progress_limit_(4 * (static_cast<std::uint64_t>(width) + static_cast<std::uint64_t>(height)) +
                      64),
      b_stamp_(width, height, 0), b_visited_(width, height, 0), wall_stamp_(width, height, 0),
      circled_(width, height, 0), b_traced_(width, height, 0) {
  tracer_[0].hand = Hand::Left;
  tracer_[1].hand = Hand::Right;
}

TeamCommand FastWallFollow::step(const TeamObservation& obs) {
  const Cell a = obs.robots[0].position, b = obs.robots[1].position;
  for (const auto& robot : obs.robots) map_.scan(robot.position, robot.neighbours);
  map_.sweep_line(a, b, obs.line_of_sight);
  TeamCommand cmd;
  if (map_.frontiers().frontier_count() == 0) {
    stage_ = Stage::Finished;
    cmd.finished = true;
  } else if (stage_ == Stage::WallFollowing) {
    cmd.move = wall_step(obs);
  } else {
    cmd.move = completion_.decide(map_, {a, b});
  }
  // The guard of the header's last choice: never a move the map itself rules out.
  for (std::size_t r = 0; r < 2; ++r) {
    const int m = cmd.move[r];
    if (m == kStay) continue;
    const Cell to = obs.robots[r].position + kernel::kNeighbours8[static_cast<std::size_t>(m)];
    if (!map_.in_bounds(to) || map_.at(to) == CellState::O) cmd.move[r] = kStay;
  }
  last_position_ = {a, b};
  sight_before_ = obs.line_of_sight;
  first_tick_ = false;
  return cmd;
}

std::array<std::int8_t, 2> FastWallFollow::end_wall_stage(Cell a, Cell b) {
  stage_ = Stage::FrontierCompletion;
  return completion_.decide(map_, {a, b});
}

void FastWallFollow::build_seek_path(Cell from, Cell to) {
  // The supercover from B to A is 4-connected; walk it with 8-connected shortcuts, stopping next
  // to A.
  const std::vector<Cell> chain = kernel::supercover(from, to);
  seek_path_.clear();
  seek_next_ = 0;
  std::size_t i = 0;
  while (i + 1 < chain.size()) {
    std::size_t j = std::min(i + 2, chain.size() - 1);
    while (j > i + 1 && chebyshev(chain[j], chain[i]) > 1) --j;
    if (chain[j] == to) break;
    seek_path_.push_back(chain[j]);
    i = j;
  }
}

int FastWallFollow::find_cause(Cell b) const {
  for (int k = 0; k < 8; ++k) {
    const Cell c = b + offset(k);
    if (map_.in_bounds(c) && map_.at(c) == CellState::O && lost_mark_[c] == lost_generation_ &&
        !circled_[c])
      return k;
  }
  return -1;
}

std::array<std::int8_t, 2> FastWallFollow::wall_step(const TeamObservation& obs) {
  const Cell a = obs.robots[0].position, b = obs.robots[1].position;
  const bool los = obs.line_of_sight;
  const bool moved_a = !first_tick_ && a != last_position_[0];
  const bool moved_b = !first_tick_ && b != last_position_[1];
  ++wall_ticks_;
  std::array<std::int8_t, 2> moves{kStay, kStay};

  if (loop_closed_ || wall_ticks_ - last_progress_tick_ > progress_limit_)
    return end_wall_stage(a, b);

  // Step 1: get onto a wall.
  if (tracer_[0].wall < 0) {
    tracer_[0].position = a;
    tracer_[0].wall = static_cast<std::int8_t>(initial_wall(map_, a, Hand::Left));
  }
  if (mode_ == TroubleShooter::FollowWalls && tracer_[1].wall < 0) {
    tracer_[1].position = b;
    tracer_[1].wall = static_cast<std::int8_t>(initial_wall(map_, b, Hand::Right));
    if (tracer_[1].wall >= 0) b_traced_[b] = 1;
  }
  const bool b_ready = mode_ != TroubleShooter::FollowWalls || tracer_[1].wall >= 0;
  if (tracer_[0].wall < 0 || !b_ready) {
    // No blocked neighbour means all eight are free: walk west (A) or south (B), unless the
    // partner is there; the one already on a wall waits.
    Cell a_next = a;
    if (tracer_[0].wall < 0 && a + offset(4) != b) {
      moves[0] = 4;
      a_next = a + offset(4);
    }
    if (!b_ready && b + offset(6) != a_next && b + offset(6) != a) moves[1] = 6;
    return moves;
  }

  // Steps 2, 4, 5: the line of sight was lost by the last moves. Neighbouring robots are never
  // out of sight: each scan sees the other robot (assumption 1), even when the line between two
  // diagonal neighbours grazes a blocked corner cell.
  const bool lost = !los && sight_before_ && (moved_a || moved_b) && chebyshev(a, b) > 1;
  // The same loss again (A at the same point of its trace, B on the same cell): stepping back
  // would repeat the same cycle forever, so B stays and A goes on (step 5).
  const bool repeated = lost && trace_index_ == last_loss_index_ && b == last_loss_b_;
  if (repeated && mode_ != TroubleShooter::Seek) {
    mode_ = TroubleShooter::Stay;
    ++meetings_;
  } else if (lost) {
    if (mode_ == TroubleShooter::Seek) {
      // Lost during B's walk toward A: B stops where it is (step 5) and A resumes.
      mode_ = TroubleShooter::Stay;
      ++meetings_;
    } else {
      ++losses_;
      last_loss_index_ = trace_index_;
      last_loss_b_ = b;
      if (++lost_generation_ == 0) {
        lost_mark_.fill(0);
        lost_generation_ = 1;
      }
      kernel::for_each_supercover_cell(a, b, [&](Cell c) {
        if (c != a && c != b) lost_mark_[c] = lost_generation_;
      });
      // Both step back (A first; if B has since moved into A's former cell, A waits).
      const Cell a_back = last_position_[0], b_back = last_position_[1];
      Cell a_next = a;
      if (moved_a && a_back != b) {
        moves[0] = static_cast<std::int8_t>(direction_of(a_back - a));
        tracer_[0] = previous_tracer_[0];
        --trace_index_;
        a_next = a_back;
      }
      if (moved_b && b_back != a_next) {
        moves[1] = static_cast<std::int8_t>(direction_of(b_back - b));
        if (mode_ == TroubleShooter::FollowCause && tracer_[1].wall >= 0 &&
            b_stamp_[tracer_[1].position] == b_generation_) // undone: not a repeat when re-entered
          b_visited_[tracer_[1].position] &= static_cast<std::uint8_t>(~(1u << tracer_[1].wall));
        tracer_[1] = previous_tracer_[1];
      }
      mode_ = TroubleShooter::Seek;
      seek_pending_ = true;
      return moves;
    }
  }

  if (seek_pending_) {
    seek_pending_ = false;
    if (los) {
      build_seek_path(b, a);
    } else {
      mode_ = TroubleShooter::Stay; // the step back did not restore sight: treat as step 5
      ++meetings_;
    }
  }

  bool a_follows = true;
  if (mode_ == TroubleShooter::Seek) {
    const int cause = find_cause(b);
    if (cause >= 0) {
      // Step 4: follow the cause on the side it lies on.
      const Cell c = b + offset(cause);
      const std::int64_t cross =
          std::int64_t{a.x - b.x} * (c.y - b.y) - std::int64_t{a.y - b.y} * (c.x - b.x);
      const Hand hand = cross >= 0 ? Hand::Right : Hand::Left; // y down: cross > 0 is the right
      tracer_[1] = {b, static_cast<std::int8_t>(cause), hand};
      if (wall_stamp_[c] != b_generation_ || b_generation_ == 0) {
        // A new obstacle: start a new record of B's way around it.
        if (++b_generation_ == 0) {
          b_stamp_.fill(0);
          wall_stamp_.fill(0);
          b_generation_ = 1;
        }
        loop_walls_.clear();
      }
      wall_stamp_[c] = b_generation_;
      loop_walls_.push_back(c);
      mode_ = TroubleShooter::FollowCause;
      ++causes_;
    } else if (chebyshev(a, b) <= 1 || seek_next_ >= seek_path_.size()) {
      mode_ = TroubleShooter::Stay; // step 5: met the partner
      ++meetings_;
    } else {
      const Cell to = seek_path_[seek_next_++];
      if (to != a) moves[1] = static_cast<std::int8_t>(direction_of(to - b));
      a_follows = false; // A waits while B walks
    }
  }

  Cell a_next = a;
  if (a_follows) {
    WallTracer next;
    const int k = trace_step(map_, tracer_[0], next);
    if (k >= 0) {
      if (b_traced_[next.position]) {
        // A reaches the outer walls B traced before it left them (step 2): every wall of this
        // boundary has now been followed by one robot or the other (step 6).
        return end_wall_stage(a, b);
      }
      if (next.position == b) {
        // B stands on A's way: two ticks running means they met head-on (step 6).
        if (++blocked_ticks_ >= 2) return end_wall_stage(a, b);
      } else {
        blocked_ticks_ = 0;
        previous_tracer_[0] = tracer_[0];
        tracer_[0] = next;
        moves[0] = static_cast<std::int8_t>(k);
        a_next = next.position;
        if (++trace_index_ > max_index_) {
          max_index_ = trace_index_;
          last_progress_tick_ = wall_ticks_;
          const auto bit = static_cast<std::uint8_t>(1u << next.wall);
          if (visited_[next.position] & bit) loop_closed_ = true; // the trace repeats: done
          visited_[next.position] |= bit;
        }
      }
    }
  }

  if (mode_ == TroubleShooter::FollowWalls || mode_ == TroubleShooter::FollowCause) {
    WallTracer next;
    const int k = trace_step(map_, tracer_[1], next);
    if (k >= 0 && next.position != a_next && next.position != a) {
      previous_tracer_[1] = tracer_[1];
      tracer_[1] = next;
      moves[1] = static_cast<std::int8_t>(k);
      if (mode_ == TroubleShooter::FollowWalls) b_traced_[next.position] = 1;
      if (mode_ == TroubleShooter::FollowCause) {
        // B has gone once around the cause when its tracing state repeats: it has detected that
        // obstacle, and stays (then relays as in step 5).
        if (b_stamp_[next.position] != b_generation_) {
          b_stamp_[next.position] = b_generation_;
          b_visited_[next.position] = 0;
        }
        const auto bit = static_cast<std::uint8_t>(1u << next.wall);
        if (b_visited_[next.position] & bit) {
          // Once around: the cause is detected; it is never a cause again (find_cause).
          mode_ = TroubleShooter::Stay;
          ++meetings_;
          for (const Cell w : loop_walls_) circled_[w] = 1;
          loop_walls_.clear();
        }
        b_visited_[next.position] |= bit;
        const Cell wall = next.position + offset(next.wall);
        if (map_.in_bounds(wall) && wall_stamp_[wall] != b_generation_) {
          wall_stamp_[wall] = b_generation_;
          loop_walls_.push_back(wall);
        }
      }
    }
  }
  return moves;
}

} // namespace antkit::los
