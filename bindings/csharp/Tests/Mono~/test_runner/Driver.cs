// Drives Tests/Runtime/UnityTestRunner.cs as Unity's Test Runner would: the [OneTimeSetUp] method,
// then the [TestCaseSource] method once per case, each case passed, ignored or failed.
//   mono HedgeTestRunner.exe   (HEDGE_DATA_DIR: the repository's data/ folder, else those checks are ignored)
using System;
using System.Reflection;
using NUnit.Framework;

namespace Hedge.Tests
{
    public static class UnityTestRunnerDriver
    {
        public static int Main()
        {
            var runner = new UnityTestRunner();
            runner.SetUpContext();
            int passed = 0, ignored = 0, failed = 0;
            foreach (TestCaseData c in UnityTestRunner.Checks())
            {
                try
                {
                    runner.Run((MethodInfo)c.Arguments[0]);
                    ++passed;
                }
                catch (IgnoreException e)
                {
                    Console.WriteLine("[ IGNORED  ] " + c.TestName + ": " + e.Message);
                    ++ignored;
                }
                catch (AssertionException e)
                {
                    Console.WriteLine("[  FAILED  ] " + c.TestName + ": " + e.Message);
                    ++failed;
                }
            }
            Console.WriteLine("through the NUnit adapter: " + passed + " passed, " + ignored + " ignored, " + failed +
                              " failed");
            return failed > 0 || passed == 0 ? 1 : 0;
        }
    }
}
