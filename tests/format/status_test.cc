// Status carries the errno of the call that failed along with its code and
// limit, so front ends need not probe the file again to learn it.
#include "linemap/status.h"

#include <gtest/gtest.h>

#include <cerrno>
#include <string>

namespace linemap {
namespace {

TEST(StatusTest, HasNoErrnoUnlessGivenOne) {
  EXPECT_EQ(Status().sys_errno(), 0);
  EXPECT_EQ(IoError("disk gone").sys_errno(), 0);
  EXPECT_EQ(OverLimitError(Limit::kCells, "too big").sys_errno(), 0);
}

TEST(StatusTest, WithErrnoKeepsTheRest) {
  const Status status = OverLimitError(Limit::kSegments, "too many").WithErrno(ENOMEM);
  EXPECT_EQ(status.code(), StatusCode::kResourceExhausted);
  EXPECT_EQ(status.limit(), Limit::kSegments);
  EXPECT_EQ(status.message(), "too many");
  EXPECT_EQ(status.sys_errno(), ENOMEM);
  EXPECT_EQ(status.WithErrno(ENOSPC).sys_errno(), ENOSPC);
}

TEST(StatusTest, AnOkStatusTakesNoErrno) {
  const Status status = Status::Ok().WithErrno(ENOENT);
  EXPECT_TRUE(status.ok());
  EXPECT_EQ(status.sys_errno(), 0);
}

TEST(StatusTest, WithContextKeepsCodeLimitAndErrno) {
  const Status status = IoError("cannot write 'a.lmap': No space left on device")
                            .WithErrno(ENOSPC)
                            .WithContext("saving")
                            .WithContext("map 3");
  EXPECT_EQ(status.code(), StatusCode::kIoError);
  EXPECT_EQ(status.limit(), Limit::kNone);
  EXPECT_EQ(status.sys_errno(), ENOSPC);
  EXPECT_EQ(status.message(), "map 3: saving: cannot write 'a.lmap': No space left on device");
  const Status over = OverLimitError(Limit::kCells, "big").WithErrno(EFBIG).WithContext("x");
  EXPECT_EQ(over.limit(), Limit::kCells);
  EXPECT_EQ(over.sys_errno(), EFBIG);
}

StatusOr<int> FailsWith(const Status& status) { return status; }

StatusOr<int> PassesOn(const Status& status) {
  LINEMAP_ASSIGN_OR_RETURN(const int value, FailsWith(status));
  return value;
}

Status ReturnsIfError(const Status& status) {
  LINEMAP_RETURN_IF_ERROR(PassesOn(status).status());
  return Status::Ok();
}

TEST(StatusTest, StatusOrAndTheMacrosKeepTheErrno) {
  const Status failed = NotFoundError("'x.lmap': no such file").WithErrno(ENOENT);
  const StatusOr<int> direct = FailsWith(failed);
  EXPECT_EQ(direct.status().sys_errno(), ENOENT);
  EXPECT_EQ(PassesOn(failed).status().sys_errno(), ENOENT);
  const Status returned = ReturnsIfError(failed);
  EXPECT_EQ(returned.code(), StatusCode::kNotFound);
  EXPECT_EQ(returned.sys_errno(), ENOENT);
  EXPECT_EQ(returned.message(), failed.message());
}

}  // namespace
}  // namespace linemap
