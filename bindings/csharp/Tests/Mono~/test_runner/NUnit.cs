// A stand-in for the few NUnit types that Tests/Runtime/UnityTestRunner.cs uses (Unity's Test
// Runner ships NUnit 3), following NUnit's documented signatures, and for UnityEngine.Application's
// temporaryCachePath: enough to compile the adapter under Mono and drive it (Driver.cs).
using System;

namespace NUnit.Framework
{
    public class TestCaseData
    {
        public TestCaseData(params object[] args) { Arguments = args; }
        public object[] Arguments { get; private set; }
        public string TestName { get; private set; }
        public TestCaseData SetName(string name)
        {
            TestName = name;
            return this;
        }
    }

    [AttributeUsage(AttributeTargets.Method)]
    public class OneTimeSetUpAttribute : Attribute
    {
    }

    [AttributeUsage(AttributeTargets.Method)]
    public class TestCaseSourceAttribute : Attribute
    {
        public TestCaseSourceAttribute(string sourceName) { SourceName = sourceName; }
        public string SourceName { get; private set; }
    }

    public class IgnoreException : Exception
    {
        public IgnoreException(string message) : base(message) { }
    }

    public class AssertionException : Exception
    {
        public AssertionException(string message) : base(message) { }
    }

    public static class Assert
    {
        public static void Ignore(string message) { throw new IgnoreException(message); }
        public static void Fail(string message) { throw new AssertionException(message); }
    }
}

namespace UnityEngine
{
    public static class Application
    {
        public static string temporaryCachePath
        {
            get { return Environment.GetEnvironmentVariable("HEDGE_STANDIN_CACHE") ?? System.IO.Path.GetTempPath(); }
        }
    }
}
