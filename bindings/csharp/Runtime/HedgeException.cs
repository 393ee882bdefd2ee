// Status codes and the one exception type of the binding.
using System;
using System.Runtime.InteropServices;
using System.Text;

namespace Hedge
{
    /// <summary>The C ABI's status codes (hedge_status).</summary>
    public enum HedgeStatus
    {
        Ok = 0,
        /// <summary>An invalid argument: a NaN coordinate, a size mismatch, an index into the input
        /// arrays out of range, an unknown enum value.</summary>
        InvalidArgument = -1,
        /// <summary>A mesh or render object that is disposed (or was never created), or an element
        /// index out of range or deleted.</summary>
        BadHandle = -2,
        /// <summary>The operation's predicate said no; nothing was changed. The binding turns this into
        /// a false / invalid result and never throws it.</summary>
        Refused = -3,
        /// <summary>A file could not be read or written, or is malformed; the message names the file and
        /// the line (text formats) or byte offset (binary formats).</summary>
        Io = -4,
        /// <summary>The input cannot be a half-edge mesh under <see cref="TopologyPolicy.Strict"/>.</summary>
        Topology = -5,
        OutOfMemory = -6,
        /// <summary>A caller array is too small; nothing was changed.</summary>
        BufferTooSmall = -7,
        /// <summary>An unexpected internal failure (a bug in the library).</summary>
        Internal = -8,
        /// <summary>The mesh is in a call on another thread. A mesh and its render buffers take calls from one
        /// thread at a time; an overlapping call fails at once with this status and changes nothing.</summary>
        Busy = -9,
    }

    /// <summary>A failed call into the native library: its status code and the library's message
    /// (hedge_last_error(), read on the calling thread right after the failed call).</summary>
    public class HedgeException : Exception
    {
        /// <summary>The status code of the failed call.</summary>
        public HedgeStatus Status { get; private set; }

        public HedgeException(HedgeStatus status, string message)
            : base(string.IsNullOrEmpty(message) ? Hedge.Status.Name(status) : message)
        {
            Status = status;
        }

        /// <summary>The status's constant name in the C ABI ("HEDGE_ERROR_BAD_HANDLE", ...).</summary>
        public string StatusName { get { return Hedge.Status.Name(Status); } }

        public override string ToString()
        {
            return GetType().FullName + " (" + StatusName + "): " + Message +
                   (StackTrace != null ? Environment.NewLine + StackTrace : "");
        }
    }

    /// <summary>Status checks and string conversions shared by the binding.</summary>
    internal static class Status
    {
        /// <summary>Throws a <see cref="HedgeException"/> unless the status is OK.</summary>
        internal static void Check(int status)
        {
            if (status != 0) throw Failure(status);
        }

        /// <summary>The value a native call wrote, once its status is checked: call, check and convert in
        /// one expression, e.g. <c>Checked(Native.f(id, out double r), r)</c>.</summary>
        internal static T Checked<T>(int status, T value)
        {
            if (status != 0) throw Failure(status);
            return value;
        }

        internal const int BufferTooSmall = (int)HedgeStatus.BufferTooSmall;

        /// <summary>The count of a "caller buffer" call, or the exception for its status. A null buffer asks
        /// for the count: BUFFER_TOO_SMALL is then the expected answer.</summary>
        internal static int Filled(int status, bool sizeQuery, ulong count)
        {
            if (status != 0 && !(sizeQuery && status == BufferTooSmall)) throw Failure(status);
            return (int)count;
        }

        /// <summary>The capacity to pass for a caller buffer: its length, 0 for null.</summary>
        internal static uint Capacity(Array buffer) { return buffer != null ? (uint)buffer.Length : 0u; }

        /// <summary>The exception for a failed status, with the thread's last error message. Call it right
        /// after the failed native call: the next call clears the message.</summary>
        internal static HedgeException Failure(int status)
        {
            return new HedgeException((HedgeStatus)status, FromUtf8(Native.hedge_last_error()));
        }

        /// <summary>The exception for a count beyond int.MaxValue, which the binding's int counts cannot hold.</summary>
        internal static OverflowException TooLarge(string what)
        {
            return new OverflowException("more than " + int.MaxValue + " " + what +
                                         ": beyond the int counts and indices of the C# binding");
        }

        internal static string Name(HedgeStatus status)
        {
            return FromUtf8(Native.hedge_status_string((int)status));
        }

        /// <summary>A NUL-terminated UTF-8 string owned by the library, as a managed string.</summary>
        internal static string FromUtf8(IntPtr text)
        {
            if (text == IntPtr.Zero) return "";
            int length = 0;
            while (Marshal.ReadByte(text, length) != 0) ++length;
            if (length == 0) return "";
            var bytes = new byte[length];
            Marshal.Copy(text, bytes, 0, length);
            return Encoding.UTF8.GetString(bytes);
        }

        /// <summary>A managed string as NUL-terminated UTF-8 (paths).</summary>
        internal static byte[] ToUtf8(string text, string parameter)
        {
            if (text == null) throw new ArgumentNullException(parameter);
            if (text.IndexOf('\0') >= 0) throw new ArgumentException("contains a NUL character", parameter);
            int n = Encoding.UTF8.GetByteCount(text);
            var bytes = new byte[n + 1];
            Encoding.UTF8.GetBytes(text, 0, text.Length, bytes, 0);
            return bytes;
        }

        /// <summary>A NUL-terminated UTF-8 buffer filled by the library, as a managed string.</summary>
        internal static string FromUtf8(byte[] buffer)
        {
            int length = Array.IndexOf(buffer, (byte)0);
            if (length < 0) length = buffer.Length;
            return Encoding.UTF8.GetString(buffer, 0, length);
        }
    }
}
